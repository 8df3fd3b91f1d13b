#pragma once
// What the ROAM and quadtree baselines share: a tessellator (visual/lod, no
// GL) rebuilds a triangle list of DEM sample indices every frame, culled to
// the view volume while it is built and behind nearer terrain after
// (lod/drawn_surface_occlusion.h, when on); drawn with shaders/level0.vert
// and the shared shading (render/sample_triangle_stream.h).

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/type_precision.hpp>

#include "lod/drawn_surface_occlusion.h"
#include "lod/roam_patch_grid.h"
#include "render/sample_triangle_stream.h"
#include "render/terrain_method.h"

namespace ig::render {

class TriangleListMethod : public TerrainMethod {
 public:
  lod::SceneRequests update(const Camera& camera) final;
  MethodFrameStats draw(const Camera& camera, const gl::RenderTarget& target) final;
  // Largest (error / distance to the piece's box) over the triangles of the
  // last update, in pixels for this viewport.
  std::optional<double> error_bound_px(const Camera& camera, int viewport_height_px) const final;
  double last_update_ms() const { return update_ms_; }

 protected:
  TriangleListMethod(const TerrainScene& scene, const std::string& shader_dir, bool horizon_culling);

  // This frame's triangles, built with in_view() as the view test; the
  // method keeps them (in its selection) until the next call.
  virtual std::vector<glm::u16vec2>& tessellate(const Camera& camera, const lod::BoxInView& in_view) = 0;
  // The last tessellation's largest error / distance (radians).
  virtual double max_error_ratio() const = 0;
  // The method's own log columns for the frame; "hidden_boxes" follows them.
  virtual std::vector<std::pair<std::string, double>> frame_columns() const = 0;

  const TerrainScene& scene_;

 private:
  SampleTriangleStream stream_;
  Frustum frustum_{};
  lod::BoxInView in_view_;
  std::unique_ptr<lod::DrawnSurfaceOcclusion> occlusion_;  // null: horizon culling off
  std::vector<glm::u16vec2>* triangles_ = nullptr;         // the last update's
  int hidden_boxes_ = 0;                                    // triangle groups hidden this frame
  double update_ms_ = 0.0;
};

}  // namespace ig::render
