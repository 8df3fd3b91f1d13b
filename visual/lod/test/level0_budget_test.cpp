// The auto Level0 budget: the reference display gets the reference budget,
// a 4x finer display twice the triangles, and the ends are clamped.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "lod/level0_budget.h"

namespace {

using ig::lod::level0_budget_for_display;
using ig::lod::pixels_per_radian;

TEST(Level0Budget, PixelsPerRadianAtTheCentre) {
  EXPECT_NEAR(pixels_per_radian(1024, 60.0), 1024.0 / (2.0 * std::tan(M_PI / 6.0)), 1e-9);
  EXPECT_NEAR(pixels_per_radian(1024, 60.0), 886.8, 0.1);
  EXPECT_NEAR(pixels_per_radian(1024, 15.0), 3889.0, 1.0);
}

TEST(Level0Budget, GrowsAsTheSquareRootOfTheAngularResolution) {
  EXPECT_EQ(level0_budget_for_display(887.0), 524288);
  EXPECT_EQ(level0_budget_for_display(4.0 * 887.0), 2 * 524288);
  // Table 2's two fields of view at 1024 rows.
  const int telephoto = level0_budget_for_display(pixels_per_radian(1024, 15.0));
  const int wide = level0_budget_for_display(pixels_per_radian(1024, 60.0));
  EXPECT_GT(telephoto, 1000000);
  EXPECT_LT(telephoto, 1150000);
  EXPECT_NEAR(wide, 524288, 1024);
  EXPECT_EQ(telephoto % 1024, 0);
}

TEST(Level0Budget, ClampedAndSafe) {
  EXPECT_EQ(level0_budget_for_display(0.01), 32768);
  EXPECT_EQ(level0_budget_for_display(1e9), 4194304);
  EXPECT_EQ(level0_budget_for_display(0.0), 524288);
  EXPECT_EQ(level0_budget_for_display(-5.0), 524288);
  EXPECT_EQ(level0_budget_for_display(std::numeric_limits<double>::quiet_NaN()), 524288);
}

}  // namespace
