#include "render/camera.h"

#include <algorithm>
#include <cmath>

#include "terrain/earth_curvature.h"

namespace ig::render {

glm::dvec3 Camera::forward() const { return attitude * glm::dvec3(0, 1, 0); }
glm::dvec3 Camera::right() const { return attitude * glm::dvec3(1, 0, 0); }
glm::dvec3 Camera::up() const { return attitude * glm::dvec3(0, 0, 1); }

glm::mat4 Camera::view_rotation() const {
  // Rows are the camera axes in world coordinates: GL x = right, y = up, z = -forward.
  const glm::dvec3 r = right(), u = up(), f = forward();
  glm::dmat4 m(1.0);
  m[0][0] = r.x; m[1][0] = r.y; m[2][0] = r.z;
  m[0][1] = u.x; m[1][1] = u.y; m[2][1] = u.z;
  m[0][2] = -f.x; m[1][2] = -f.y; m[2][2] = -f.z;
  return glm::mat4(m);
}

glm::mat4 Camera::projection() const {
  const double t = 1.0 / std::tan(glm::radians(fov_y_deg) * 0.5);
  glm::dmat4 p(0.0);
  p[0][0] = t / aspect;
  p[1][1] = t;
  // depth = near * (far - d) / (d * (far - near)), d = -z_view: near -> 1, far -> 0.
  p[2][2] = near_m / (far_m - near_m);
  p[3][2] = near_m * far_m / (far_m - near_m);
  p[2][3] = -1.0;
  return glm::mat4(p);
}

double Camera::depth_to_view_distance(float depth) const {
  // Invert depth = near*(far-d)/(d*(far-near)).
  const double z = depth;
  return near_m * far_m / (z * (far_m - near_m) + near_m);
}

glm::dvec3 Camera::pixel_ray(double px, double py, int width, int height) const {
  const double t = std::tan(glm::radians(fov_y_deg) * 0.5);
  const double nx = ((px + 0.5) / width * 2.0 - 1.0) * t * aspect;
  const double ny = (1.0 - (py + 0.5) / height * 2.0) * t;
  return glm::normalize(forward() + right() * nx + up() * ny);
}

Frustum frustum_of(const Camera& camera) {
  // Planes from the combined matrix (Gribb-Hartmann), in double.
  const glm::dmat4 m = glm::dmat4(camera.view_projection());
  auto row = [&](int i) { return glm::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
  Frustum f;
  f.planes[0] = row(3) + row(0);  // left
  f.planes[1] = row(3) - row(0);  // right
  f.planes[2] = row(3) + row(1);  // bottom
  f.planes[3] = row(3) - row(1);  // top
  f.planes[4] = row(3) - row(2);  // near (reversed: depth <= 1)
  f.planes[5] = row(2);           // far (depth >= 0)
  for (auto& p : f.planes) p /= glm::length(glm::dvec3(p));
  f.earth_radius_m = camera.earth_radius_m;
  return f;
}

namespace {
// An eye-relative flat-terrain box as drawn with curvature: heights are
// z - drop(d), so the nearest horizontal point drops least, the farthest corner most.
void lower_by_curvature(glm::dvec3& lo, glm::dvec3& hi, double earth_radius_m) {
  if (earth_radius_m <= 0.0) return;
  const double nx = std::max(lo.x, std::min(0.0, hi.x)), ny = std::max(lo.y, std::min(0.0, hi.y));
  const double fx = std::max(std::abs(lo.x), std::abs(hi.x)), fy = std::max(std::abs(lo.y), std::abs(hi.y));
  hi.z -= terrain::curvature_drop_squared(nx * nx + ny * ny, earth_radius_m);
  lo.z -= terrain::curvature_drop_squared(fx * fx + fy * fy, earth_radius_m);
}
}  // namespace

glm::ivec4 screen_rect_of_box(const Camera& camera, glm::dvec3 lo, glm::dvec3 hi, int width, int height) {
  lower_by_curvature(lo, hi, camera.earth_radius_m);
  const glm::dmat4 vp = glm::dmat4(camera.view_projection());
  double x0 = 1e30, y0 = 1e30, x1 = -1e30, y1 = -1e30;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec4 c = vp * glm::dvec4(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z, 1.0);
    if (c.w <= camera.near_m) return {0, 0, width, height};  // near or behind the eye: no bound
    x0 = std::min(x0, c.x / c.w);
    x1 = std::max(x1, c.x / c.w);
    y0 = std::min(y0, c.y / c.w);
    y1 = std::max(y1, c.y / c.w);
  }
  auto px = [](double ndc, int size) { return std::clamp(int(std::floor((ndc * 0.5 + 0.5) * size)), 0, size); };
  // One pixel of margin for rasterisation rounding.
  return {std::max(px(x0, width) - 1, 0), std::max(px(y0, height) - 1, 0), std::min(px(x1, width) + 1, width),
          std::min(px(y1, height) + 1, height)};
}

bool Frustum::intersects_box(const glm::dvec3& box_lo, const glm::dvec3& box_hi) const {
  glm::dvec3 lo = box_lo, hi = box_hi;
  lower_by_curvature(lo, hi, earth_radius_m);
  for (const auto& p : planes) {
    const glm::dvec3 v(p.x >= 0 ? hi.x : lo.x, p.y >= 0 ? hi.y : lo.y, p.z >= 0 ? hi.z : lo.z);
    if (p.x * v.x + p.y * v.y + p.z * v.z + p.w < 0) return false;
  }
  return true;
}

}  // namespace ig::render
