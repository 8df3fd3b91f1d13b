#include "lod/projected_area.h"

#include <cmath>

#include <glm/vec4.hpp>

namespace ig::lod {
namespace {

// Keeps the part of `poly` where dot(plane, v) >= 0 (Sutherland-Hodgman).
std::vector<glm::dvec4> clip(const std::vector<glm::dvec4>& poly, const glm::dvec4& plane) {
  std::vector<glm::dvec4> out;
  for (size_t k = 0; k < poly.size(); ++k) {
    const glm::dvec4& a = poly[k];
    const glm::dvec4& b = poly[(k + 1) % poly.size()];
    const double da = glm::dot(plane, a), db = glm::dot(plane, b);
    if (da >= 0) out.push_back(a);
    if ((da >= 0) != (db >= 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

}  // namespace

double projected_area_px(const glm::dmat4& view_proj, const std::vector<glm::dvec3>& corners, int width,
                         int height) {
  std::vector<glm::dvec4> poly;
  for (const auto& c : corners) poly.push_back(view_proj * glm::dvec4(c, 1.0));
  // In front of the eye (w > 0, a little margin against division by ~0), then inside the four sides.
  for (const glm::dvec4& plane : {glm::dvec4(0, 0, 0, 1) - glm::dvec4(0, 0, 0, 1e-9), glm::dvec4(1, 0, 0, 1),
                                  glm::dvec4(-1, 0, 0, 1), glm::dvec4(0, 1, 0, 1), glm::dvec4(0, -1, 0, 1)}) {
    poly = clip(poly, plane);
    if (poly.size() < 3) return 0.0;
  }
  double twice = 0.0;
  for (size_t k = 0; k < poly.size(); ++k) {
    const glm::dvec4& a = poly[k];
    const glm::dvec4& b = poly[(k + 1) % poly.size()];
    twice += (a.x / a.w) * (b.y / b.w) - (b.x / b.w) * (a.y / a.w);
  }
  return std::abs(twice) * 0.5 * (0.5 * width) * (0.5 * height);  // NDC spans 2 units each way
}

}  // namespace ig::lod
