// The shoreline between samples: the texture's rows and the point queries
// agree, and a straight coast at any angle comes out straight, not as the
// stair-steps of its cells.
#include "water/shore_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "water/test/water_test_terrain.h"
#include "water/water_detection.h"

namespace ig::water {
namespace {

// A map of one body: the samples whose centres lie below the line
// j = slope * i + c (a straight coast at any angle).
WaterMap coast(int w, int h, double slope, double c) {
  WaterMap map(w, h);
  WaterBody b;
  b.level_m = 5.0f;
  map.bodies().push_back(b);
  for (int j = 0; j < h; ++j) {
    std::vector<WaterRun> runs;
    int begin = -1;
    for (int i = 0; i <= w; ++i) {
      const bool water = i < w && double(j) < slope * i + c;
      if (water && begin < 0) begin = i;
      if (!water && begin >= 0) {
        runs.push_back({begin, i, 0});
        begin = -1;
      }
    }
    map.add_row(j, runs);
  }
  map.summarise_bodies(1.0);
  return map;
}

TEST(ShoreField, RowsAreThePointFieldQuantised) {
  const terrain::Heightfield hf = test::make_water_test_terrain();
  const WaterMap map = detect_water(hf);
  int rows = 0;
  for_each_shore_row(map, 1, [&](int j, const std::uint8_t* share, const std::uint8_t* mask) {
    EXPECT_EQ(j, rows++);
    for (int i = 0; i < map.width(); ++i) {
      ASSERT_EQ(share[i], shore_byte(shore_share_at_sample(map, i, j))) << i << "," << j;
      ASSERT_EQ(mask[i] != 0, map.is_water(i, j)) << i << "," << j;
    }
  });
  EXPECT_EQ(rows, map.height());
}

TEST(ShoreField, HalfwayBetweenWaterAndLandAndWholeAwayFromIt) {
  const WaterMap map = coast(40, 40, 0.0, 20.0);  // rows 0..19 water
  // Across a straight coast the share falls through 1/2 halfway between the
  // last water sample and the first land one.
  EXPECT_NEAR(shore_share_at_sample(map, 10, 19) + shore_share_at_sample(map, 10, 20), 1.0, 1e-12);
  EXPECT_GT(shore_share_at_sample(map, 10, 19), 0.5);
  EXPECT_EQ(shore_byte(shore_share_at_sample(map, 10, 5)), 255);
  EXPECT_EQ(shore_share_at_sample(map, 10, 35), 0.0);
  EXPECT_EQ(shore_byte(shore_share_at_sample(map, 10, 0)), 255);  // the sea goes on beyond the edge
  const auto mid = shore_at(map, 10.3, 19.5);
  ASSERT_TRUE(mid);
  EXPECT_NEAR(mid->share, 0.5f, 0.01f);
  const auto wet = shore_at(map, 10.3, 19.4);
  ASSERT_TRUE(wet && wet->body);
  EXPECT_TRUE(wet->water());
  EXPECT_EQ(*wet->body, 0u);
  const auto dry = shore_at(map, 10.3, 19.6);
  ASSERT_TRUE(dry);
  EXPECT_FALSE(dry->water());
  EXPECT_FALSE(dry->body);
  EXPECT_FALSE(shore_at(map, -0.1, 5.0));
  EXPECT_FALSE(shore_at(map, 5.0, 39.01));
  EXPECT_FALSE(shore_at(map, std::nan(""), 5.0));
}

// Along a straight coast the shore stays within a quarter sample of the
// coast's line; the water cells' own outline (the stair-steps of a mask
// drawn by cells) strays more than half a sample from it.
TEST(ShoreField, AStraightCoastStaysStraight) {
  for (double angle_deg : {10.0, 23.0, 37.0, 52.0, 71.0}) {
    const double slope = std::tan(angle_deg * M_PI / 180.0), c = 40.3 - 40.0 * slope;
    const WaterMap map = coast(80, 80, slope, c);
    // The line the cells stand for: the coast's slope through the mean of
    // the cells' outline (halfway between each column's last water sample
    // and first land one).
    auto outline = [&](int i) { return std::ceil(slope * i + c) - 0.5; };
    double offset = 0.0;
    for (int i = 30; i <= 50; ++i) offset += outline(i) - slope * i;
    offset /= 21.0;
    const double across = std::cos(std::atan(slope));  // vertical offsets to distances across the coast
    double worst = 0.0, worst_cells = 0.0;
    for (double si = 30.0; si <= 50.0; si += 0.05) {
      double lo = 0.0, hi = 79.0;  // bisect for the shore in this column
      for (int k = 0; k < 40; ++k) {
        const double m = 0.5 * (lo + hi);
        (shore_at(map, si, m)->water() ? lo : hi) = m;
      }
      const double line = slope * si + offset;
      worst = std::max(worst, std::abs(lo - line) * across);
      worst_cells = std::max(worst_cells, std::abs(outline(int(std::lround(si))) - line) * across);
    }
    // Measured: 0.14-0.25 samples against the cells' 0.56-0.70.
    EXPECT_LT(worst, 0.3) << angle_deg << " deg";
    EXPECT_LT(worst, 0.5 * worst_cells) << angle_deg << " deg";
  }
}

TEST(ShoreField, OverviewGridTakesEveryStepthSample) {
  const WaterMap map = coast(41, 21, 0.0, 10.0);
  const ShoreGrid g = shore_grid(map, 4);
  EXPECT_EQ(g.width, 11);
  EXPECT_EQ(g.height, 6);
  int rows = 0;
  for_each_shore_row(map, 4, [&](int j, const std::uint8_t*, const std::uint8_t* mask) {
    ++rows;
    for (int i = 0; i < g.width; ++i) EXPECT_EQ(mask[i] != 0, map.is_water(4 * i, 4 * j));
  });
  EXPECT_EQ(rows, 6);
}

}  // namespace
}  // namespace ig::water
