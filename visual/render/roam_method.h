#pragma once
// Baseline "roam": view-dependent ROAM (Duchaineau et al. 1997) rebuilt from
// the patch roots every frame with a screen-space tolerance tau (pixels),
// forced splits for a crack-free mesh and frustum culling
// (lod/roam_tessellator.h, docs/baselines.md). One triangle list of DEM
// sample indices per frame, drawn with level0.vert and the shared shading.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lod/drawn_surface_occlusion.h"
#include "lod/roam_tessellator.h"
#include "render/sample_triangle_stream.h"
#include "render/terrain_method.h"

namespace ig::render {

using options::RoamOptions;  // options/method_options.h

class RoamMethod final : public TerrainMethod {
 public:
  // Throws std::invalid_argument for a negative or non-finite tau.
  RoamMethod(const TerrainScene& scene, const std::string& shader_dir, RoamOptions options = {});
  std::string name() const override { return "roam"; }
  std::vector<std::string> column_names() const override;
  void set_viewport(int width_px, int height_px) override;
  lod::SceneRequests update(const Camera& camera) override;
  MethodFrameStats draw(const Camera& camera, const gl::RenderTarget& target) override;
  std::optional<ErrorKnob> knob() const override { return ErrorKnob{"tau_px", "px", options_.tau_px}; }
  // Largest (wedgie / distance to the triangle's box) over the triangles of
  // the last update, in pixels for this viewport.
  std::optional<double> error_bound_px(const Camera& camera, int viewport_height_px) const override;

  const lod::RoamTessellator& tessellator() const { return tess_; }
  const lod::RoamSelection& selection() const { return selection_; }
  double last_update_ms() const { return update_ms_; }

 private:
  const TerrainScene& scene_;
  RoamOptions options_;
  lod::RoamTessellator tess_;
  lod::RoamSelection selection_;  // update() -> draw()
  std::unique_ptr<lod::DrawnSurfaceOcclusion> occlusion_;  // null: horizon culling off
  int hidden_boxes_ = 0;  // triangle groups hidden this frame
  SampleTriangleStream stream_;
  Frustum frustum_{};
  lod::BoxInView in_view_;
  double update_ms_ = 0.0;
};

}  // namespace ig::render
