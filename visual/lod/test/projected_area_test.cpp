// Projected polygon area (lod/projected_area.h) against cases with known answers.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "lod/projected_area.h"

namespace {

using ig::lod::projected_area_px;

TEST(ProjectedArea, SquareFacingTheEyeAndClippedToTheViewport) {
  // Orthographic-like check with a perspective: a square at distance d with
  // half side s covers (s/d / tan(fov/2))^2 of the NDC square's quarter.
  const glm::dmat4 proj = glm::perspective(glm::radians(90.0), 1.0, 0.1, 1000.0);  // looks down -z
  const double d = 10.0, s = 2.0;
  const std::vector<glm::dvec3> square = {{-s, -s, -d}, {s, -s, -d}, {s, s, -d}, {-s, s, -d}};
  const double ndc_half = s / d;  // tan(45 deg) = 1
  EXPECT_NEAR(projected_area_px(proj, square, 100, 100), (2 * ndc_half * 50) * (2 * ndc_half * 50), 1e-6);
  // A huge square fills the viewport exactly.
  const std::vector<glm::dvec3> huge = {{-1e3, -1e3, -d}, {1e3, -1e3, -d}, {1e3, 1e3, -d}, {-1e3, 1e3, -d}};
  EXPECT_NEAR(projected_area_px(proj, huge, 100, 80), 8000.0, 1e-6);
  // Behind the eye: nothing.
  std::vector<glm::dvec3> behind = square;
  for (auto& c : behind) c.z = d;
  EXPECT_EQ(projected_area_px(proj, behind, 100, 100), 0.0);
}

TEST(ProjectedArea, GroundPlaneCrossingTheEyePlaneIsClippedAtTheNearPlane) {
  // Looking along -z, a ground square from behind the eye to far ahead: only
  // the part in front counts, and it stays below the horizon (lower half).
  const glm::dmat4 proj = glm::perspective(glm::radians(60.0), 1.0, 0.5, 1e5);
  const std::vector<glm::dvec3> ground = {{-1e4, -10, 1e4}, {1e4, -10, 1e4}, {1e4, -10, -1e4}, {-1e4, -10, -1e4}};
  const double a = projected_area_px(proj, ground, 200, 200);
  EXPECT_GT(a, 0.0);
  EXPECT_LT(a, 200.0 * 100.0);  // at most the lower half
  EXPECT_GT(a, 0.9 * 200.0 * 100.0);
}

}  // namespace
