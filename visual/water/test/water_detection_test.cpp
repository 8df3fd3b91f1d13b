// Water found in the DEM: what an SRTM edit leaves is water, the traps
// beside it are not, and a paged load finds what the whole load finds.
#include "water/water_detection.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "terrain/dem_loader.h"
#include "terrain/test/temp_dir_fixture.h"
#include "terrain/test/test_geotiff.h"
#include "water/test/water_test_terrain.h"

namespace ig::water {
namespace {

using test::kLakeLevel;
using test::make_water_test_terrain;
using test::TestFeatures;

TEST(WaterDetection, FindsTheLakeAndTheSeaAndNothingElse) {
  const TestFeatures f;
  const terrain::Heightfield hf = make_water_test_terrain(200, 150, f);
  const WaterMap map = detect_water(hf);
  ASSERT_EQ(map.bodies().size(), 2u);
  EXPECT_EQ(map.source(), "auto");
  // Bodies come south first: the sea (rows 0..11), then the lake.
  const WaterBody& sea = map.bodies()[0];
  const WaterBody& lake = map.bodies()[1];
  EXPECT_EQ(sea.kind, WaterKind::Sea);
  EXPECT_EQ(sea.level_m, 0.0f);
  EXPECT_TRUE(sea.touches_edge);
  EXPECT_EQ(sea.samples, std::int64_t(200) * f.sea_rows);
  EXPECT_EQ(lake.kind, WaterKind::Lake);
  EXPECT_EQ(lake.level_m, kLakeLevel);
  EXPECT_FALSE(lake.touches_edge);
  std::int64_t lake_samples = 0;
  for (int j = 0; j < hf.height; ++j)
    for (int i = 0; i < hf.width; ++i) {
      // The disc's four tips stick out one sample wide (no 2 x 2 block): land.
      const bool tip = (std::abs(i - f.lake_i) == f.lake_r && j == f.lake_j) ||
                       (std::abs(j - f.lake_j) == f.lake_r && i == f.lake_i);
      const bool in_lake = hf.at(i, j) == kLakeLevel && !tip;
      lake_samples += in_lake;
      EXPECT_EQ(map.body_at(i, j) == std::optional<std::uint32_t>(1), in_lake) << i << "," << j;
    }
  EXPECT_EQ(lake.samples, lake_samples);
  EXPECT_DOUBLE_EQ(lake.area_m2, double(lake_samples) * 90.0 * 90.0);
  EXPECT_EQ(lake.min_i, f.lake_i - f.lake_r + 1);
  EXPECT_EQ(lake.max_j, f.lake_j + f.lake_r - 1);
  // The traps: a pond below the minimum size, 1 m terraces, a playa whose
  // rim is a 1 m step, and the 0 m ring around dry land below sea level.
  EXPECT_FALSE(map.is_water(f.pond_i + 1, f.pond_j + 1));
  for (int j = f.sea_rows; j < f.sea_rows + f.terrace_rows; ++j) EXPECT_FALSE(map.is_water(100, j)) << j;
  EXPECT_FALSE(map.is_water(f.playa_i, f.playa_j));
  for (int i = f.below_i - f.below_r - 3; i < hf.width; ++i) EXPECT_FALSE(map.is_water(i, f.below_j)) << i;
}

TEST(WaterDetection, RegionsSayWhyTheyAreNotWater) {
  const TestFeatures f;
  const terrain::Heightfield hf = make_water_test_terrain(200, 150, f);
  const std::vector<FlatRegion> regions = flat_regions(hf, 9);
  // The region of `height` whose first (southernmost) row is `first_j` (a
  // disc's one-sample tip is in no 2 x 2 block: its first row is the next).
  auto region = [&](float height, int first_j) -> const FlatRegion* {
    for (const FlatRegion& r : regions)
      if (r.height_m == height && r.first_j == first_j) return &r;
    return nullptr;
  };
  const FlatRegion* playa = region(test::kPlayaLevel, f.playa_j - f.playa_r + 1);
  ASSERT_NE(playa, nullptr);
  EXPECT_FALSE(playa->water);
  EXPECT_EQ(playa->lower, 0);             // a closed basin...
  EXPECT_EQ(playa->steps, playa->rim);    // ...whose rim is a 1 m step all round
  const FlatRegion* pond = region(1250.0f, f.pond_j);
  ASSERT_NE(pond, nullptr);
  EXPECT_EQ(pond->samples, 9);
  EXPECT_FALSE(pond->water);              // 9 x 8100 m2 < 600 m x 183 m
  const FlatRegion* terrace = region(101.0f, f.sea_rows + 8);
  ASSERT_NE(terrace, nullptr);
  EXPECT_FALSE(terrace->water);           // half its rim is lower, the rest a 1 m step
  EXPECT_EQ(terrace->steps, terrace->rim);
  const FlatRegion* ring = region(0.0f, f.below_j - f.below_r - 2);
  ASSERT_NE(ring, nullptr);
  EXPECT_TRUE(ring->touches_edge);
  EXPECT_GT(double(ring->lower), 0.3 * double(ring->rim));  // it surrounds lower ground
  EXPECT_FALSE(ring->water);
}

TEST(WaterDetection, MinimumSizeIsTheSwbdsSmallestLake) {
  // A square lake of n x n samples at 90 m: kept from 600 m x 183 m up.
  for (int n : {3, 4, 5}) {
    TestFeatures f;
    f.lake_r = 0;
    f.sea_rows = f.terrace_rows = 0;
    terrain::Heightfield hf = make_water_test_terrain(60, 60, f);
    for (int j = 20; j < 20 + n; ++j)
      for (int i = 20; i < 20 + n; ++i) hf.ref(i, j) = 1000.0f;
    const WaterMap map = detect_water(hf);
    const bool big_enough = n * n * 8100.0 >= 600.0 * 183.0;
    EXPECT_EQ(map.is_water(21, 21), big_enough) << n;
  }
}

TEST(WaterDetection, FlatGroundWithoutEditsHasNoWater) {
  terrain::Heightfield hf;
  hf.width = hf.height = 64;
  hf.spacing_x_m = hf.spacing_y_m = 30.0;
  hf.heights.resize(64 * 64);
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) hf.ref(i, j) = 100.0f + 0.37f * float(i) + 0.11f * float(j * j % 7);
  EXPECT_TRUE(detect_water(hf).empty());
  // One sample wide or high: no 2 x 2 block, no water.
  hf.width = 1;
  hf.heights.resize(64);
  EXPECT_TRUE(detect_water(hf).empty());
}

class WaterDetectionPaged : public terrain::test::TempDirTest {
 protected:
  WaterDetectionPaged() : TempDirTest("ig_water_paged_") {}
};

TEST_F(WaterDetectionPaged, PagedFindsWhatTheWholeLoadFinds) {
  // 1100 x 1000 floats (4.4 MB) over a 1 MB budget: paged in 256^2 tiles,
  // the features repeated across tile boundaries.
  TestFeatures f;
  f.sea_rows = 300;
  f.lake_i = 250;
  f.lake_j = 500;
  f.lake_r = 40;
  const terrain::Heightfield made = make_water_test_terrain(1100, 1000, f);
  const std::string path = (dir_ / "water.tif").string();
  terrain::test::write_south_first_geotiff(path, made.width, made.height, made.heights, -32768.0);
  terrain::DemLoadOptions paged_opts;
  paged_opts.memory_budget_mb = 1;
  const terrain::Heightfield whole = terrain::load_dem(path);
  const terrain::Heightfield paged = terrain::load_dem(path, paged_opts);
  ASSERT_TRUE(paged.paged);
  ASSERT_FALSE(whole.paged);
  const WaterMap a = detect_water(whole), b = detect_water(paged);
  EXPECT_EQ(a.bodies().size(), 2u);
  EXPECT_TRUE(a == b);
  EXPECT_EQ(a.water_samples(), b.water_samples());
}

}  // namespace
}  // namespace ig::water
