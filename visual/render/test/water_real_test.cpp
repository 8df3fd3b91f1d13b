// Water on the real tiles of $IG_DEM_DIR: the Tahoe shore from 30 m against
// a 4 x 4 supersampled render, and the Sierra paged (over a small memory
// budget) drawing the same water as the whole load.
#include <gtest/gtest.h>

#include <cstdio>

#include "picture_checks.h"

namespace {

using picture::Shot;
using picture::ShotSpec;

ig::io::Scenario scenario(const std::string& file) {
  return ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/" + file);
}

ig::io::Scenario without_water(ig::io::Scenario s) {
  s.terrain.water.source = ig::options::WaterSource::Off;
  return s;
}

// Pixels whose 4 x 4 block in the supersampled render holds both water
// (where water on and off differ) and land, no sky: mean |difference| of
// `shot` from the box-filtered supersampled render there.
struct ShoreError {
  double mean = 0.0;
  long long pixels = 0;
};
ShoreError shore_error(const Shot& shot, const Shot& ss_with, const Shot& ss_without) {
  const Shot ss = picture::box_filter(ss_with, 4);
  ShoreError e;
  double sum = 0.0;
  for (int y = 1; y + 1 < shot.h; ++y)
    for (int x = 1; x + 1 < shot.w; ++x) {
      int water = 0, sky = 0;
      for (int v = 0; v < 4; ++v)
        for (int u = 0; u < 4; ++u) {
          const std::size_t q = std::size_t(y * 4 + v) * ss_with.w + (x * 4 + u);
          bool differs = false;
          for (int k = 0; k < 3; ++k) differs = differs || ss_with.rgba[q * 4 + k] != ss_without.rgba[q * 4 + k];
          water += differs;
          sky += ss_with.depth[q] == 0.0f;
        }
      if (water == 0 || water == 16 || sky > 0) continue;
      const std::size_t p = std::size_t(y) * shot.w + x;
      double d = 0.0;
      for (int k = 0; k < 3; ++k) d += std::abs(int(shot.rgba[p * 4 + k]) - int(ss.rgba[p * 4 + k]));
      sum += d / 3.0;
      ++e.pixels;
    }
  e.mean = e.pixels ? sum / double(e.pixels) : 0.0;
  return e;
}

TEST(WaterReal, TahoeShoreIsCloseToSupersampled) {
  if (picture::dem_dir().empty()) GTEST_SKIP() << "IG_DEM_DIR not set: real-DEM water test skipped";
  const auto s = scenario("tahoe_shore_30m.json");
  const int w = 320, h = 240;
  const Shot ss_with = picture::render(s, 0, ShotSpec{4 * w, 4 * h, "off", true, "twolevel"});
  const Shot ss_without = picture::render(without_water(s), 0, ShotSpec{4 * w, 4 * h, "off", true, "twolevel"});
  for (const char* aa : {"fxaa", "off"}) {
    const ShoreError e = shore_error(picture::render(s, 0, ShotSpec{w, h, aa, true, "twolevel"}), ss_with, ss_without);
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
