#pragma once
// The reference renderer: the full-resolution mesh (every DEM sample a
// vertex), drawn as fixed-size chunks of one shared grid mesh with per-chunk
// frustum culling. Ground truth for every image-error measurement.

#include <vector>

#include "gl/grid_mesh.h"
#include "gl/shader_program.h"
#include "render/terrain_method.h"

namespace ig::render {

class ReferenceMethod final : public TerrainMethod {
 public:
  ReferenceMethod(const TerrainScene& scene, const std::string& shader_dir, int chunk_quads = 64);
  std::string name() const override { return "reference"; }
  std::vector<std::string> column_names() const override { return {"chunks_drawn", "chunks_total"}; }
  lod::SceneRequests update(const Camera& camera) override;
  MethodFrameStats draw(const Camera& camera, const gl::RenderTarget& target) override;
  // Every DEM sample is a vertex: no geometric error by construction.
  std::optional<double> error_bound_px(const Camera&, int) const override { return 0.0; }

  struct Chunk {
    int i0, j0;            // origin sample
    int quads_x, quads_y;  // real quads (edge chunks are smaller)
    float min_h, max_h;
  };
  // One frame's selection: the chunks in the view frustum (indices into chunks()).
  struct Selection {
    std::vector<int> visible;
  };
  Selection select(const Camera& camera) const;
  const Selection& selection() const { return selection_; }
  const std::vector<Chunk>& chunks() const { return chunks_; }

 private:
  const TerrainScene& scene_;
  gl::ShaderProgram program_;
  gl::GridMesh mesh_;
  std::vector<Chunk> chunks_;
  Selection selection_;
};

}  // namespace ig::render
