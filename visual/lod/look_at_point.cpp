#include "lod/look_at_point.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "terrain/ray_cast.h"

namespace ig::lod {

LookAtPoint find_look_at_point(const terrain::Heightfield& hf, const terrain::HeightPyramid& pyramid,
                               const glm::dvec3& eye, const glm::dvec3& dir, const glm::dvec3& hint,
                               double fallback_distance_m) {
  LookAtPoint e;
  if (const auto hit = terrain::cast_ray(hf, pyramid, eye, dir)) {
    e.point = hit->point;
    e.hit = true;
    return e;
  }
  const double ex = std::clamp(eye.x, 0.0, hf.extent_x_m()), ey = std::clamp(eye.y, 0.0, hf.extent_y_m());
  glm::dvec2 h(dir.x, dir.y);
  const double hlen = glm::length(h);
  if (hlen > 1e-9) h /= hlen;
  else if (glm::length(glm::dvec2(hint)) > 1e-9) h = glm::normalize(glm::dvec2(hint));
  else h = {0.0, 1.0};
  const double agl = std::max(eye.z - hf.sample_surface(ex, ey), 1.0);
  double d = fallback_distance_m;
  if (std::isfinite(dir.z) && dir.z < 0.0) d = std::min(d, agl * hlen / -dir.z);
  const double x = std::clamp(ex + h.x * d, 0.0, hf.extent_x_m());
  const double y = std::clamp(ey + h.y * d, 0.0, hf.extent_y_m());
  e.point = {x, y, hf.sample_surface(x, y)};
  return e;
}

}  // namespace ig::lod
