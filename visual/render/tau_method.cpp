#include "render/tau_method.h"

#include <cmath>
#include <stdexcept>

namespace ig::render {
namespace {
double checked_tau(const std::string& name, double tau_px) {
  if (!(tau_px > 0.0) || !std::isfinite(tau_px))
    throw std::invalid_argument(name + ": tau_px must be a positive number of pixels, got " + std::to_string(tau_px));
  return tau_px;
}
}  // namespace

TauMethod::TauMethod(const std::string& name, const TerrainScene& scene, const std::string& shader_dir,
                     const std::string& vertex_shader, double tau_px, bool horizon_culling)
    : scene_(scene),
      tau_px_(checked_tau(name, tau_px)),
      program_(shader_dir, vertex_shader, scene.shading_stages({"terrain.frag"})) {
  if (horizon_culling) occlusion_ = std::make_unique<lod::DrawnSurfaceOcclusion>(scene.heightfield(), scene.height_pyramid());
}

void TauMethod::set_viewport(int, int height_px) {
  if (height_px > 0) viewport_h_ = height_px;
}

TauMethod::Placement TauMethod::begin_draw(const Camera& camera) const {
  program_.use();
  scene_.bind_common(program_, camera);
  return {gl::Uniform(program_, "u_origin"), gl::Uniform(program_, "u_origin_rel")};
}

void TauMethod::place(const Placement& p, const Camera& camera, int i0, int j0) const {
  const auto& hf = scene_.heightfield();
  // Eye-relative origin in double, then to float: no precision loss far from the origin.
  const glm::dvec3 rel = glm::dvec3(i0 * hf.spacing_x_m, j0 * hf.spacing_y_m, 0.0) - camera.position;
  p.origin.set(glm::ivec2(i0, j0));
  p.origin_rel.set(glm::vec3(rel));
}

}  // namespace ig::render
