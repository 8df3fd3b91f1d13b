#pragma once
// Baseline "roam": view-dependent ROAM (Duchaineau et al. 1997) rebuilt from
// the patch roots every frame with a screen-space tolerance tau (pixels),
// forced splits for a crack-free mesh and frustum culling
// (lod/roam_tessellator.h, docs/baselines.md). One triangle list of DEM
// sample indices per frame, drawn with level0.vert and the shared shading.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lod/roam_tessellator.h"
#include "render/triangle_list_method.h"

namespace ig::render {

using options::RoamOptions;  // options/method_options.h

class RoamMethod final : public TriangleListMethod {
 public:
  // Throws std::invalid_argument for a negative or non-finite tau.
  RoamMethod(const TerrainScene& scene, const std::string& shader_dir, RoamOptions options = {});
  std::string name() const override { return "roam"; }
  std::vector<std::string> column_names() const override;
  void set_viewport(int width_px, int height_px) override;
  std::optional<ErrorKnob> knob() const override { return ErrorKnob{"tau_px", "px", options_.tau_px}; }

  const lod::RoamTessellator& tessellator() const { return tess_; }
  const lod::RoamSelection& selection() const { return selection_; }

 private:
  std::vector<glm::u16vec2>& tessellate(const Camera& camera, const lod::BoxInView& in_view) override;
  double max_error_ratio() const override { return selection_.stats.max_error_ratio; }
  std::vector<std::pair<std::string, double>> frame_columns() const override;

  RoamOptions options_;
  lod::RoamTessellator tess_;
  lod::RoamSelection selection_;  // update() -> draw()
};

}  // namespace ig::render
