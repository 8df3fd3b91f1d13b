#include "render/triangle_list_method.h"

#include <algorithm>
#include <chrono>

namespace ig::render {

TriangleListMethod::TriangleListMethod(const TerrainScene& scene, const std::string& shader_dir,
                                       bool horizon_culling)
    : scene_(scene), stream_(scene, shader_dir) {
  in_view_ = [this](const glm::dvec3& lo, const glm::dvec3& hi) { return frustum_.intersects_box(lo, hi); };
  if (horizon_culling)
    occlusion_ = std::make_unique<lod::DrawnSurfaceOcclusion>(scene.heightfield(), scene.height_pyramid());
}

lod::SceneRequests TriangleListMethod::update(const Camera& camera) {
  const auto t0 = std::chrono::steady_clock::now();
  frustum_ = frustum_of(camera);
  triangles_ = &tessellate(camera, in_view_);
  hidden_boxes_ = occlusion_ ? occlusion_->cull_triangles(camera.position, camera.earth_radius_m,
                                                          10.0 * camera.near_m, *triangles_)
                             : 0;
  update_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return {};
}

MethodFrameStats TriangleListMethod::draw(const Camera& camera, const gl::RenderTarget&) {
  static const std::vector<glm::u16vec2> kNone;
  const auto& triangles = triangles_ ? *triangles_ : kNone;
  auto columns = frame_columns();
  columns.emplace_back("hidden_boxes", double(hidden_boxes_));
  return stream_.draw_frame(triangles, scene_, camera, (long long)triangles.size() / 3, std::move(columns));
}

std::optional<double> TriangleListMethod::error_bound_px(const Camera& camera, int viewport_height_px) const {
  return max_error_ratio() * pixels_per_radian(camera, viewport_height_px);
}

}  // namespace ig::render
