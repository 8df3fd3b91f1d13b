#pragma once
// GeoMipMapping (de Boer 2000) as a terrain method: the DEM in 33 x 33-vertex
// blocks (lod/geomipmap_blocks.h), each drawn at the coarsest mip level
// whose projected error rho = delta * pixels_per_radian / D is at most tau_px
// (D: distance from the eye to the block's bounding box, delta: the level's
// precomputed max vertical error). Sides next to coarser blocks are stitched
// to the neighbour's stride, so there are no cracks. One vertex buffer of
// 33 x 33 offsets, one index buffer per configuration (level + side levels,
// built on first use), drawn with shaders/terrain_grid.vert and the shared
// shading; blocks are culled against the view frustum.

#include <unordered_map>
#include <vector>

#include "gl/static_mesh.h"
#include "lod/geomipmap_blocks.h"
#include "options/method_options.h"
#include "render/tau_method.h"

namespace ig::render {

class GeoMipMapMethod final : public TauMethod {
 public:
  // Throws std::invalid_argument unless tau_px > 0 (finite).
  GeoMipMapMethod(const TerrainScene& scene, const std::string& shader_dir, options::GeoMipMapOptions options = {});
  GeoMipMapMethod(const TerrainScene& scene, const std::string& shader_dir, double tau_px)
      : GeoMipMapMethod(scene, shader_dir, options::GeoMipMapOptions{tau_px}) {}
  GeoMipMapMethod(const GeoMipMapMethod&) = delete;
  GeoMipMapMethod& operator=(const GeoMipMapMethod&) = delete;

  std::string name() const override { return "geomipmap"; }
  std::vector<std::string> column_names() const override;
  lod::SceneRequests update(const Camera& camera) override;
  MethodFrameStats draw(const Camera& camera, const gl::RenderTarget& target) override;
  // Max over the pieces of the drawn blocks of (error of the triangles
  // drawn) / max(distance to the piece, near), in pixels. The pieces: the
  // plain level quads (the level's error, from the block's box) and each
  // stitched side's strip (its own error, from the strip's box), so a block
  // under the eye stitched to a coarser neighbour is judged at that edge.
  std::optional<double> error_bound_px(const Camera& camera, int viewport_height_px) const override;

  struct DrawnBlock {
    int bx = 0, by = 0;
    lod::GeoMipConfig config;
    double distance_m = 0.0;
    float error_m = 0.0f;  // bound on all its triangles, stitching included (GeoMipMapBlocks::stats)
    int triangles = 0;
    double error_per_m = 0.0;  // max over its pieces of error / max(distance, near)
  };
  // One frame's selection: every block's level (culled ones too: a visible
  // block's stitching depends on its neighbours' levels) and the blocks to draw.
  struct Selection {
    std::vector<int> levels;
    std::vector<DrawnBlock> drawn;
  };
  Selection select(const Camera& camera) const;
  const lod::GeoMipMapBlocks& blocks() const { return blocks_; }
  const std::vector<int>& levels() const { return selection_.levels; }  // every block's level
  const std::vector<DrawnBlock>& drawn() const { return selection_.drawn; }

 private:
  // The index list of a configuration in mesh_, built on first use.
  int indices_for(const lod::GeoMipConfig& config);

  lod::GeoMipMapBlocks blocks_;
  gl::StaticMesh mesh_;  // the block's 33 x 33 vertices
  std::unordered_map<std::uint32_t, int> indices_;
  Selection selection_;  // the last update's
};

}  // namespace ig::render
