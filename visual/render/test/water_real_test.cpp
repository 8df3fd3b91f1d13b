// Water on the real tiles of $IG_DEM_DIR: the Tahoe shore from 30 m against
// a 4 x 4 supersampled render, and the Sierra paged (over a small memory
// budget) drawing the same water as the whole load.
#include <gtest/gtest.h>

#include <cstdio>

#include "picture_checks.h"
#include "water_checks.h"

namespace {

using picture::Shot;
using picture::ShotSpec;
using water_checks::ShoreError;
using water_checks::without_water;

ig::io::Scenario scenario(const std::string& file) {
  return ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/" + file);
}

TEST(WaterReal, TahoeShoreIsCloseToSupersampled) {
  if (picture::dem_dir().empty()) GTEST_SKIP() << "IG_DEM_DIR not set: real-DEM water test skipped";
  const auto s = scenario("tahoe_shore_30m.json");
  const int w = 320, h = 240;
  const Shot ss_with = picture::render(s, 0, ShotSpec{4 * w, 4 * h, "off", true, "twolevel"});
  const Shot ss_without = picture::render(without_water(s), 0, ShotSpec{4 * w, 4 * h, "off", true, "twolevel"});
  for (const char* aa : {"fxaa", "off"}) {
    const ShoreError e =
        water_checks::shore_error(picture::render(s, 0, ShotSpec{w, h, aa, true, "twolevel"}), ss_with, ss_without);
    std::printf("[water shore, Tahoe 30 m] %s: %lld shore pixels, mean |difference| from 16x SS %.2f levels\n", aa,
                e.pixels, e.mean);
    EXPECT_GT(e.pixels, 100);
    EXPECT_LE(e.mean, 10.0) << aa;
  }
}

TEST(WaterReal, PagedSierraDrawsTheSameWater) {
  if (picture::dem_dir().empty()) GTEST_SKIP() << "IG_DEM_DIR not set: real-DEM water test skipped";
  auto s = scenario("tahoe_shore_30m.json");
  const int w = 240, h = 180;
  const Shot whole = picture::render(s, 0, ShotSpec{w, h, "off", true, "twolevel"});
  s.terrain.memory_budget_mb = 48;  // 64 MB of heights: paged
  s.terrain.wait_for_pages = true;
  const Shot paged = picture::render(s, 0, ShotSpec{w, h, "off", true, "twolevel"});
  const Shot dry = picture::render(without_water(s), 0, ShotSpec{w, h, "off", true, "twolevel"});
  const double d = picture::mean_abs_difference(whole, paged);
  const double wet = picture::mean_abs_difference(paged, dry);
  std::printf("[water paged] Tahoe view paged vs whole: mean |difference| %.3f levels; with and without water %.1f\n", d,
              wet);
  EXPECT_LT(d, 0.5);
  EXPECT_GT(wet, 5.0);
}

}  // namespace
