#pragma once
// Chunked LOD (Ulrich 2002) as a terrain method. A precomputed quadtree of
// chunks (lod/chunk_quadtree.h): each chunk is a 32 x 32-quad regular grid at
// a stride of 2^(depth - level) samples (leaves: full resolution), with its
// measured max vertical error delta (made monotone up the tree, so a parent's
// delta bounds its children's; on natural terrain it roughly halves per
// level). Per frame the tree is walked from the root, refining a chunk while
// its projected error delta * pixels_per_radian / D exceeds tau_px (D: eye
// to the chunk's bounding box), culling against the view frustum.
//
// Cracks between chunks of different levels are hidden by skirts: each
// chunk's edge vertices are repeated hanging down to below every height the
// neighbouring chunk's edge can take there (see skirt_bottom in the .cpp);
// sides on the DEM's outer edge get none. No morphing: a chunk that splits
// changes shape at once (a pop of at most tau_px). One shared grid + skirt
// mesh, shaders/chunked.vert, the shared shading.

#include <vector>

#include "gl/static_mesh.h"
#include "lod/chunk_quadtree.h"
#include "options/method_options.h"
#include "render/tau_method.h"

namespace ig::render {

class ChunkedMethod final : public TauMethod {
 public:
  // Throws std::invalid_argument unless tau_px > 0 (finite).
  ChunkedMethod(const TerrainScene& scene, const std::string& shader_dir, options::ChunkedOptions options = {});
  ChunkedMethod(const TerrainScene& scene, const std::string& shader_dir, double tau_px)
      : ChunkedMethod(scene, shader_dir, options::ChunkedOptions{tau_px}) {}
  ChunkedMethod(const ChunkedMethod&) = delete;
  ChunkedMethod& operator=(const ChunkedMethod&) = delete;

  std::string name() const override { return "chunked"; }
  std::vector<std::string> column_names() const override;
  lod::SceneRequests update(const Camera& camera) override;
  MethodFrameStats draw(const Camera& camera, const gl::RenderTarget& target) override;
  // Max over drawn chunks of (the chunk mesh's own measured error) /
  // max(D, near), in pixels; skirts hang below the surface and add none.
  std::optional<double> error_bound_px(const Camera& camera, int viewport_height_px) const override;

  // One frame's selection is the chunks to draw, each with its skirt depth.
  struct DrawnChunk {
    int node = 0;
    double distance_m = 0.0;
    float skirt_bottom_m = 0.0f;  // absolute height the skirts reach down to
  };
  std::vector<DrawnChunk> select(const Camera& camera) const;
  const lod::ChunkQuadtree& tree() const { return tree_; }
  const std::vector<DrawnChunk>& drawn() const { return drawn_; }

 private:
  lod::ChunkQuadtree tree_;
  gl::StaticMesh mesh_;  // the grid, then each side's skirt
  int surface_indices_ = 0;
  std::vector<DrawnChunk> drawn_;  // the last update's selection
};

}  // namespace ig::render
