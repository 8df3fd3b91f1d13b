#include "render/roam_method.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace ig::render {

RoamMethod::RoamMethod(const TerrainScene& scene, const std::string& shader_dir, RoamOptions options)
    : scene_(scene), options_(options), tess_(scene.heightfield(), scene.earth_radius_m()), stream_(scene, shader_dir) {
  if (!(options_.tau_px >= 0.0) || !std::isfinite(options_.tau_px))
    throw std::invalid_argument("roam: tau_px must be a finite value >= 0 (got " + std::to_string(options_.tau_px) +
                                ")");
  if (options_.viewport_height_px < 1) options_.viewport_height_px = 1024;
  in_view_ = [this](const glm::dvec3& lo, const glm::dvec3& hi) { return frustum_.intersects_box(lo, hi); };
  if (options_.horizon_culling) occlusion_ = std::make_unique<lod::DrawnSurfaceOcclusion>(scene.heightfield(), scene.height_pyramid());
}

std::vector<std::string> RoamMethod::column_names() const {
  return {"splits", "forced_splits", "bintree_nodes", "culled_leaves", "hidden_boxes"};
}

void RoamMethod::set_viewport(int, int height_px) {
  if (height_px > 0) options_.viewport_height_px = height_px;
}

lod::SceneRequests RoamMethod::update(const Camera& camera) {
  const auto t0 = std::chrono::steady_clock::now();
  frustum_ = frustum_of(camera);
  selection_ = tess_.select(camera.position, options_.tau_px, pixels_per_radian(camera, options_.viewport_height_px),
                            in_view_, std::max(camera.near_m, 1e-3), std::move(selection_));
  hidden_boxes_ = 0;
  if (occlusion_) {
    hidden_boxes_ = occlusion_->cull_triangles(camera.position, camera.earth_radius_m, 10.0 * camera.near_m,
                                               selection_.vertices);
    selection_.stats.triangles = (long long)selection_.vertices.size() / 3;
  }
  update_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return {};
}

MethodFrameStats RoamMethod::draw(const Camera& camera, const gl::RenderTarget&) {
  const auto& s = selection_.stats;
  return stream_.draw_frame(selection_.vertices, scene_, camera, s.triangles,
                            {{"splits", double(s.splits)},
                             {"forced_splits", double(s.forced_splits)},
                             {"bintree_nodes", double(s.nodes)},
                             {"culled_leaves", double(s.culled)},
                             {"hidden_boxes", double(hidden_boxes_)}});
}

std::optional<double> RoamMethod::error_bound_px(const Camera& camera, int viewport_height_px) const {
  return selection_.stats.max_error_ratio * pixels_per_radian(camera, viewport_height_px);
}

}  // namespace ig::render
