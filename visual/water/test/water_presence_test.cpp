// Where water shows, coarsely: each level the mean share of the blocks
// below it, halving down to one texel, a byte of 0 only where the water
// would change a pixel by under half a level.
#include "water/water_presence.h"

#include <gtest/gtest.h>

#include <numeric>

#include "water/shore_field.h"

namespace ig::water {
namespace {

// A map of w x h samples with one body on rectangle [i0, i1) x [j0, j1).
WaterMap rectangle(int w, int h, int i0, int i1, int j0, int j1) {
  WaterMap map(w, h);
  map.bodies().push_back(WaterBody{});
  for (int j = 0; j < h; ++j) {
    std::vector<WaterRun> runs;
    if (j >= j0 && j < j1) runs.push_back({i0, i1, 0});
    map.add_row(j, runs);
  }
  map.summarise_bodies(1.0);
  return map;
}

TEST(WaterPresence, LevelsHalveDownToOneTexel) {
  const auto levels = water_presence(rectangle(101, 37, 10, 20, 10, 20), 1);
  // 101 share texels / 4 -> 26 -> 32 wide; 37 / 4 -> 10 -> 16 high.
  ASSERT_FALSE(levels.empty());
  EXPECT_EQ(levels[0].width, 32);
  EXPECT_EQ(levels[0].height, 16);
  for (std::size_t k = 1; k < levels.size(); ++k) {
    EXPECT_EQ(levels[k].width, std::max(levels[k - 1].width / 2, 1));
    EXPECT_EQ(levels[k].height, std::max(levels[k - 1].height / 2, 1));
  }
  EXPECT_EQ(levels.back().width, 1);
  EXPECT_EQ(levels.back().height, 1);
}

TEST(WaterPresence, MeanShareOfTheBlockBelow) {
  const WaterMap map = rectangle(64, 64, 16, 48, 16, 48);
  const auto levels = water_presence(map, 1);
  // Level 0 texel (5, 5) covers samples 20..23, all deep in the water: 255.
  EXPECT_EQ(levels[0].texels[5 * levels[0].width + 5], 255);
  // Far from it: 0; the blur's reach beside the shore: between.
  EXPECT_EQ(levels[0].texels[0], 0);
  const int shore = levels[0].texels[5 * levels[0].width + 3];  // samples 12..15: the blur reaches them
  EXPECT_GT(shore, 0);
  EXPECT_LT(shore, 255);
  // The top level is the whole grid's mean share, about the water's part.
  std::uint64_t sum = 0;
  for_each_shore_row(map, 1, [&](int, const std::uint8_t* s, const std::uint8_t*) {
    sum = std::accumulate(s, s + 64, sum);
  });
  EXPECT_NEAR(levels.back().texels[0], double(sum) / (64.0 * 64.0), 1.0);
}

TEST(WaterPresence, ASmallPondShowsWhileItMattersAndNotBeyond) {
  // A 2 x 2 pond in 256^2: present at the fine levels, rounded away once a
  // texel's mean share is under half a level.
  const auto levels = water_presence(rectangle(256, 256, 100, 102, 100, 102), 1);
  int last_present = -1;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    const auto& l = levels[k];
    const int block = 4 << k;
    const int at = (100 / block) * l.width + 100 / block;
    if (l.texels[at] > 0) last_present = int(k);
  }
  EXPECT_GE(last_present, 1);
  EXPECT_LT(last_present, int(levels.size()) - 1);
}

TEST(WaterPresence, NoWaterNoPresence) {
  const auto levels = water_presence(rectangle(50, 50, 0, 0, 0, 0), 1);
  for (const auto& l : levels)
    for (std::uint8_t t : l.texels) ASSERT_EQ(t, 0);
}

}  // namespace
}  // namespace ig::water
