#pragma once
// CDLOD (Strugar 2010) as a terrain method: the chunk quadtree
// (lod/chunk_quadtree.h) selected by distance (lod/cdlod_selection.h: LOD
// ranges doubling per level, Strugar's quadtree walk, whole nodes or node
// quarters), one shared 32 x 32-quad grid drawn per selected piece, scaled to
// its LOD, with vertex morphing in shaders/cdlod.vert over the last third of
// each range, so there are no cracks and no pops.
//
// Knob: lod0_range, the range of the finest LOD in DEM sample spacings
// (metres = value * sqrt(spacing_x * spacing_y)). Each quad of LOD k spans
// 2^k samples and is drawn at distances up to 2^k * lod0_range samples, so
// a quad subtends at least about 1 / lod0_range radians: larger is finer.
// Being distance-based, the selection ignores roughness; the claimed error
// bound (error_bound_px) uses the measured per-node errors.

#include <array>
#include <memory>
#include <vector>

#include "gl/grid_mesh.h"
#include "gl/shader_program.h"
#include "lod/cdlod_selection.h"
#include "lod/drawn_surface_occlusion.h"
#include "lod/chunk_quadtree.h"
#include "options/method_options.h"
#include "render/terrain_method.h"

namespace ig::render {

class CdlodMethod final : public TerrainMethod {
 public:
  // Throws std::invalid_argument unless lod0_range > 0 (finite).
  CdlodMethod(const TerrainScene& scene, const std::string& shader_dir, options::CdlodOptions options = {});
  CdlodMethod(const TerrainScene& scene, const std::string& shader_dir, double lod0_range)
      : CdlodMethod(scene, shader_dir, options::CdlodOptions{lod0_range}) {}
  CdlodMethod(const CdlodMethod&) = delete;
  CdlodMethod& operator=(const CdlodMethod&) = delete;

  std::string name() const override { return "cdlod"; }
  std::vector<std::string> column_names() const override;
  lod::SceneRequests update(const Camera& camera) override;
  MethodFrameStats draw(const Camera& camera, const gl::RenderTarget& target) override;
  std::optional<ErrorKnob> knob() const override { return ErrorKnob{"lod0_range", "samples", lod0_range_}; }
  // Max over drawn pieces and over the LODs their points can show (LOD k
  // from the piece's nearest point on, each coarser LOD from where the
  // previous one's morph ends): the node error of that LOD (max of the two in
  // a morph zone) / distance, in pixels. Exact for unmorphed vertices; for
  // triangles mid-morph it is an estimate, not a proof.
  std::optional<double> error_bound_px(const Camera& camera, int viewport_height_px) const override;

  const lod::ChunkQuadtree& tree() const { return tree_; }
  const lod::CdlodRanges& ranges() const { return ranges_; }
  // One frame's selection: the nodes and node quarters to draw, each with its LOD.
  std::vector<lod::CdlodArea> select(const Camera& camera) const;
  const std::vector<lod::CdlodArea>& areas() const { return areas_; }

 private:
  const TerrainScene& scene_;
  double lod0_range_;
  gl::ShaderProgram program_;
  lod::ChunkQuadtree tree_;
  lod::CdlodRanges ranges_;
  std::vector<std::array<int, 4>> quadrant_triangles_;  // per node
  gl::GridMesh mesh_;  // the one Q x Q grid, drawn whole or a quarter at a time
  std::vector<lod::CdlodArea> areas_;  // the last update's selection
  std::unique_ptr<lod::DrawnSurfaceOcclusion> occlusion_;  // null: horizon culling off
  int hidden_boxes_ = 0;
};

}  // namespace ig::render
