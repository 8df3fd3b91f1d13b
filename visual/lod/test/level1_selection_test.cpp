// The two-level method's Level1 selection without GL: eye guard, band
// width, culled blocks in front-to-back order.

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "lod/level1_selection.h"
#include "terrain/height_pyramid.h"
#include "terrain/heightfield.h"

namespace {

using ig::lod::guard_level1_for_eye;
using ig::lod::Level1Placement;

const std::vector<int> kLadder = {33, 65, 129, 257, 513, 1025};
const glm::ivec2 kDem{4097, 4097};

TEST(Level1Selection, EyeGuardLeavesAHighEyeOrOneOffTheDemAlone) {
  const Level1Placement p{65, {2000, 2000}, false};
  // Level0 error 20 m: the guard acts below 200 m above the ground.
  auto high = guard_level1_for_eye(p, {1900.0, 2000.0}, 250.0, 20.0, kLadder, kDem);
  EXPECT_EQ(high.n, 65);
  EXPECT_EQ(high.centre, p.centre);
  EXPECT_FALSE(high.eye_guarded);
  auto outside = guard_level1_for_eye(p, {-5.0, 2000.0}, 10.0, 20.0, kLadder, kDem);
  EXPECT_EQ(outside.n, 65);
  EXPECT_FALSE(outside.eye_guarded);
}

TEST(Level1Selection, EyeGuardGrowsLevel1ToHoldALowEyeWithItsMargin) {
  const Level1Placement p{65, {2000, 2000}, false};
  // 100 samples from E: needs 2 * 100 + 2 * 32 + 1 = 265 -> 513 on the ladder.
  const auto g = guard_level1_for_eye(p, {1900.0, 2010.0}, 50.0, 20.0, kLadder, kDem);
  EXPECT_EQ(g.n, 513);
  EXPECT_EQ(g.centre, p.centre);
  EXPECT_TRUE(g.eye_guarded);
  // The eye is inside the square with the margin.
  EXPECT_LE(std::abs(1900.0 - g.centre.x), 0.5 * (g.n - 1) - ig::lod::kEyeGuardMarginSamples);
  // Already large enough: kept, not guarded.
  const auto big = guard_level1_for_eye({1025, {2000, 2000}, false}, {1900.0, 2010.0}, 50.0, 20.0, kLadder, kDem);
  EXPECT_EQ(big.n, 1025);
  EXPECT_FALSE(big.eye_guarded);
}

TEST(Level1Selection, EyeGuardMovesTheSquareWhenEvenTheLargestCannotHoldBoth) {
  const Level1Placement p{129, {3000, 2000}, false};
  const glm::dvec2 eye{1000.0, 2000.0};  // 2000 samples from E
  const auto g = guard_level1_for_eye(p, eye, 30.0, 20.0, kLadder, kDem);
  EXPECT_EQ(g.n, 1025);
  EXPECT_TRUE(g.eye_guarded);
  // The square starts the margin behind the eye, towards E.
  const double half = 0.5 * (g.n - 1);
  EXPECT_NEAR(g.centre.x - half, eye.x - ig::lod::kEyeGuardMarginSamples, 1.0);
  EXPECT_EQ(g.centre.y, 2000);
}

TEST(Level1Selection, BandWidthRoundedToTheStrideWithinItsLimits) {
  // r0 * alpha * w1 = 0.001 * 2000 * 128 = 256 -> capped at w1 / 4 = 32.
  EXPECT_EQ(ig::lod::band_width_samples(0.001, 2000.0, 129, 2), 32);
  // 0.0001 * 2000 * 128 = 25.6 -> 26 (stride 2).
  EXPECT_EQ(ig::lod::band_width_samples(0.0001, 2000.0, 129, 2), 26);
  // Tiny: at least one stride.
  EXPECT_EQ(ig::lod::band_width_samples(1e-9, 2000.0, 129, 4), 4);
  EXPECT_EQ(ig::lod::band_width_samples(0.0001, 2000.0, 129, 0), 26);  // stride < 1 counts as 1
}

TEST(Level1Selection, BlocksCulledByTheBoxTestAndSortedNearestFirst) {
  ig::terrain::Heightfield hf;
  hf.width = hf.height = 257;
  hf.spacing_x_m = hf.spacing_y_m = 10.0;
  hf.heights.assign(size_t(hf.width) * hf.height, 0.0f);
  for (int j = 0; j < hf.height; ++j)
    for (int i = 0; i < hf.width; ++i) hf.ref(i, j) = float(i);  // a ramp east
  hf.finalize_stats();
  const ig::terrain::HeightPyramid pyramid(hf);
  const glm::ivec2 origin{0, 0};
  const int n = 257;  // 8 x 8 blocks
  int calls = 0;
  // Keep blocks whose box reaches east of x = 1000 m; check the boxes' heights.
  const auto blocks = ig::lod::visible_level1_blocks(
      hf, pyramid, origin, n, 5.0,
      [&](const glm::dvec3& lo, const glm::dvec3& hi) {
        ++calls;
        EXPECT_NEAR(lo.z, lo.x / 10.0 - 5.0, 1.0);  // the cells' lowest height, lowered by 5 m
        EXPECT_NEAR(hi.z, hi.x / 10.0, 1.0);
        return hi.x > 1000.0;
      },
      glm::dvec2(256.0, 128.0));
  EXPECT_EQ(calls, 64);
  EXPECT_EQ(blocks.size(), 8u * 5u);  // block columns from x = 96 samples on
  const glm::dvec2 eye(256.0, 128.0);
  for (size_t k = 1; k < blocks.size(); ++k) {
    const glm::dvec2 a = glm::dvec2(blocks[k - 1]) + 16.0 - eye, b = glm::dvec2(blocks[k]) + 16.0 - eye;
    EXPECT_LE(glm::dot(a, a), glm::dot(b, b));
  }
}

}  // namespace
