// Level1 at its smallest when E is far out, drawn (the rule itself is
// unit-tested without GL in lod/test/twolevel_selection_test.cpp): when even
// the largest Level1 square around E reaches no terrain nearer than where
// Level0's largest error is under half a pixel, a larger Level1 could not
// show anything, so it takes the smallest ladder size, placed under the eye.
// A near view keeps the controller's size.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "render/terrain_method.h"
#include "render/test/lod_view_checks.h"

namespace {

TEST(Level1Far, AFarLookAtPointGetsTheSmallestSquare) {
  lod_views::World world;  // 513^2 at 30 m
  ig::render::TwoLevelOptions options;
  options.max_level1 = 65;     // ladder 33, 65: the largest square reaches 1.4 km from E
  options.level0_budget = 8192;  // a coarse Level0: metres of error
  ig::render::TwoLevelMethod method(*world.scene, world.shader_dir, options);
  const double s = world.hf.spacing_x_m;
  // High over one corner, looking across the map at a low angle: E ~20 km out.
  const auto far_view = lod_views::camera_at(world.hf, 10 * s, 10 * s, 3000.0, 45.0, -8.0);
  lod_views::render(world, method, far_view);
  const double distance = glm::length(method.look_at().point - far_view.position);
  const double reach = 0.5 * std::sqrt(2.0) * 64 * s;
  const double error_px = method.level0().max_error_m * ig::render::pixels_per_radian(far_view, lod_views::kH) /
                          (distance - reach);
  std::printf("far view: E %.0f m away, Level0's largest error %.2f m = %.3f px at the square's nearest reach\n",
              distance, method.level0().max_error_m, error_px);
  ASSERT_LT(error_px, ig::render::TwoLevelMethod::kFarLevel0ErrorPx) << "the view is not far enough for the rule";
  EXPECT_TRUE(method.level1_far());
  EXPECT_EQ(method.level1_size(), 33);
  const glm::ivec2 o = method.level1_origin();
  EXPECT_LE(o.x, 10);  // the square holds the eye's sample (10, 10), not E's
  EXPECT_LE(o.y, 10);

  // Looking down near the eye: the rule does not apply, the controller sizes Level1.
  const auto near_view = lod_views::camera_at(world.hf, 250 * s, 250 * s, 150.0, 45.0, -30.0);
  for (int k = 0; k < 4; ++k) lod_views::render(world, method, near_view);
  EXPECT_FALSE(method.level1_far());
}

}  // namespace
