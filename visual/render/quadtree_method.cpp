#include "render/quadtree_method.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace ig::render {

QuadtreeMethod::QuadtreeMethod(const TerrainScene& scene, const std::string& shader_dir, QuadtreeOptions options)
    : scene_(scene), options_(options), tess_(scene.heightfield()), stream_(scene, shader_dir) {
  if (!(options_.c1 > 0.0) || !std::isfinite(options_.c1) || !(options_.c2 >= 0.0) || !std::isfinite(options_.c2))
    throw std::invalid_argument("quadtree: C1 must be > 0 and C2 >= 0, both finite (got C1 = " +
                                std::to_string(options_.c1) + ", C2 = " + std::to_string(options_.c2) + ")");
  in_view_ = [this](const glm::dvec3& lo, const glm::dvec3& hi) { return frustum_.intersects_box(lo, hi); };
  if (options_.horizon_culling) occlusion_ = std::make_unique<lod::DrawnSurfaceOcclusion>(scene.heightfield(), scene.height_pyramid());
}

std::vector<std::string> QuadtreeMethod::column_names() const {
  return {"nodes_evaluated", "splits", "forced_splits", "leaves", "culled_leaves", "hidden_boxes"};
}

lod::SceneRequests QuadtreeMethod::update(const Camera& camera) {
  const auto t0 = std::chrono::steady_clock::now();
  frustum_ = frustum_of(camera);
  selection_ = tess_.select(camera.position, options_.c1, options_.c2, in_view_, std::max(camera.near_m, 1e-3),
                            std::move(selection_));
  hidden_boxes_ = 0;
  if (occlusion_) {
    hidden_boxes_ = occlusion_->cull_triangles(camera.position, camera.earth_radius_m, 10.0 * camera.near_m,
                                               selection_.vertices);
    selection_.stats.triangles = (long long)selection_.vertices.size() / 3;
  }
  update_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return {};
}

MethodFrameStats QuadtreeMethod::draw(const Camera& camera, const gl::RenderTarget&) {
  const auto& s = selection_.stats;
  return stream_.draw_frame(selection_.vertices, scene_, camera, s.triangles,
                            {{"nodes_evaluated", double(s.evaluated)},
                             {"splits", double(s.splits)},
                             {"forced_splits", double(s.forced_splits)},
                             {"leaves", double(s.leaves)},
                             {"culled_leaves", double(s.culled)},
                             {"hidden_boxes", double(hidden_boxes_)}});
}

std::optional<double> QuadtreeMethod::error_bound_px(const Camera& camera, int viewport_height_px) const {
  return selection_.stats.max_error_ratio * pixels_per_radian(camera, viewport_height_px);
}

}  // namespace ig::render
