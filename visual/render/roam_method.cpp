#include "render/roam_method.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace ig::render {

RoamMethod::RoamMethod(const TerrainScene& scene, const std::string& shader_dir, RoamOptions options)
    : TriangleListMethod(scene, shader_dir, options.horizon_culling),
      options_(options),
      tess_(scene.heightfield(), scene.earth_radius_m()) {
  if (!(options_.tau_px >= 0.0) || !std::isfinite(options_.tau_px))
    throw std::invalid_argument("roam: tau_px must be a finite value >= 0 (got " + std::to_string(options_.tau_px) +
                                ")");
  if (options_.viewport_height_px < 1) options_.viewport_height_px = 1024;
}

std::vector<std::string> RoamMethod::column_names() const {
  return {"splits", "forced_splits", "bintree_nodes", "culled_leaves", "hidden_boxes"};
}

void RoamMethod::set_viewport(int, int height_px) {
  if (height_px > 0) options_.viewport_height_px = height_px;
}

std::vector<glm::u16vec2>& RoamMethod::tessellate(const Camera& camera, const lod::BoxInView& in_view) {
  selection_ = tess_.select(camera.position, options_.tau_px, pixels_per_radian(camera, options_.viewport_height_px),
                            in_view, std::max(camera.near_m, 1e-3), std::move(selection_));
  return selection_.vertices;
}

std::vector<std::pair<std::string, double>> RoamMethod::frame_columns() const {
  const auto& s = selection_.stats;
  return {{"splits", double(s.splits)},
          {"forced_splits", double(s.forced_splits)},
          {"bintree_nodes", double(s.nodes)},
          {"culled_leaves", double(s.culled)}};
}

}  // namespace ig::render
