// Day, dusk and night from environment.time_utc: real frames of the default
// scenario (its generated terrain is placed at 46.5 N, 7.9 E by
// terrain.generator.origin), rendered headless and read back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "io/scenario.h"
#include "io/utc_time.h"
#include "render/test/headless_run.h"
#include "session/scenario_runner.h"

namespace {

using ig::session::RunOptions;
using ig::session::ScenarioRunner;

constexpr int kW = 320, kH = 240;

ig::io::Scenario default_at(const std::string& time_utc) {
  auto s = ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json");
  s.render.shading.sun_direction.reset();  // the time places the sun
  std::string why;
  const auto t = ig::io::parse_utc_time(time_utc, why);
  EXPECT_TRUE(t.has_value()) << why;
  s.render.shading.time_utc = t;
  return s;
}

RunOptions small_headless() {
  return headless_run(kW, kH);
}

// Luma (Rec. 709 weights, 8-bit levels) of the sky and the terrain pixels of frame 0.
struct Frame {
  double sun_elevation_deg = 0.0;
  std::vector<double> sky, terrain;
  double mean(const std::vector<double>& v) const {
    double s = 0.0;
    for (double x : v) s += x;
    return v.empty() ? 0.0 : s / double(v.size());
  }
};

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[std::size_t(q * double(v.size() - 1))];
}

Frame render(const std::string& time_utc) {
  ScenarioRunner runner(default_at(time_utc), small_headless());
  runner.render_frame(0);
  const auto& target = *runner.channels().front().target;
  const auto rgba = target.read_rgba();
  const auto depth = target.read_depth();
  Frame f;
  f.sun_elevation_deg = runner.sun().elevation_deg;
  for (std::size_t p = 0; p < std::size_t(kW) * kH; ++p) {
    const double l = 0.2126 * rgba[4 * p] + 0.7152 * rgba[4 * p + 1] + 0.0722 * rgba[4 * p + 2];
    (depth[p] > 0.0f ? f.terrain : f.sky).push_back(l);
  }
  return f;
}

TEST(SunAndSky, NightSkyIsDarkAndDaySkyBright) {
  // Midwinter midnight and midsummer noon at the generator's origin.
  const Frame night = render("2026-12-21T23:00:00Z");
  const Frame day = render("2026-06-21T11:30:00Z");
  std::printf("night: sun %.1f deg, sky %.1f, terrain %.1f; day: sun %.1f deg, sky %.1f, terrain %.1f, "
              "terrain p10-p90 %.1f (8-bit luma)\n",
              night.sun_elevation_deg, night.mean(night.sky), night.mean(night.terrain), day.sun_elevation_deg,
              day.mean(day.sky), day.mean(day.terrain), percentile(day.terrain, 0.9) - percentile(day.terrain, 0.1));
  EXPECT_LT(night.sun_elevation_deg, -18.0);
  EXPECT_GT(day.sun_elevation_deg, 60.0);
  ASSERT_GT(night.sky.size(), std::size_t(kW * kH / 10));  // the view has sky in it
  ASSERT_GT(day.sky.size(), std::size_t(kW * kH / 10));
  EXPECT_LT(night.mean(night.sky), 40.0);
  EXPECT_GT(day.mean(day.sky), 100.0);
  EXPECT_LT(night.mean(night.terrain), day.mean(day.terrain) / 4.0);
}

TEST(SunAndSky, DuskTerrainIsReadable) {
  // Civil twilight (sun 0 to 6 deg below the horizon), about 15 minutes
  // after sunset on midsummer's day. Readable means: the terrain is not
  // black (mean luma at least 25 of 255, a tenth of full scale), its relief
  // shows (the terrain's 10th to 90th luma percentiles span at least 10 % of
  // its mean and 4 levels; the noon frame of this gentle meadow spans about
  // 14 %), and the skyline stands out (the sky is at least 20 levels
  // brighter than the terrain on average).
  const Frame dusk = render("2026-06-21T19:45:00Z");
  const double mean = dusk.mean(dusk.terrain), spread = percentile(dusk.terrain, 0.9) - percentile(dusk.terrain, 0.1);
  std::printf("dusk: sun %.2f deg, terrain mean %.1f, p10-p90 %.1f, sky mean %.1f (8-bit luma)\n",
              dusk.sun_elevation_deg, mean, spread, dusk.mean(dusk.sky));
  EXPECT_LT(dusk.sun_elevation_deg, 0.0);
  EXPECT_GT(dusk.sun_elevation_deg, -6.0);
  ASSERT_GT(dusk.terrain.size(), std::size_t(kW * kH / 2));
  EXPECT_GE(mean, 25.0);
  EXPECT_GE(spread, 0.1 * mean);
  EXPECT_GE(spread, 4.0);
  EXPECT_GE(dusk.mean(dusk.sky) - mean, 20.0);
}

TEST(SunAndSky, SunFollowsTheScenarioClock) {
  // 20 s of the default flight at 19:40 UTC: the sun sinks by about 0.05 deg.
  ScenarioRunner runner(default_at("2026-06-21T19:40:00Z"), small_headless());
  const double at_start = runner.sun().elevation_deg;
  runner.render_frame(400);  // 20 s in
  EXPECT_LT(runner.sun().elevation_deg, at_start - 0.02);
  EXPECT_GT(runner.sun().elevation_deg, at_start - 0.2);
  EXPECT_GT(runner.sun().azimuth_deg, 290.0);  // north-west at a midsummer sunset
  EXPECT_LT(runner.sun().azimuth_deg, 320.0);
}

TEST(SunAndSky, TimeWithoutAPlaceIsRefused) {
  auto s = default_at("2026-06-21T12:00:00Z");
  s.terrain.generator->origin_lat_lon.reset();
  try {
    ScenarioRunner runner(s, small_headless());
    FAIL() << "a time_utc on terrain without a georeference should be refused";
  } catch (const ig::io::ScenarioError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("environment.time_utc"), std::string::npos) << msg;
    EXPECT_NE(msg.find("georeference"), std::string::npos) << msg;
  }
  // An explicit direction needs no place.
  s.render.shading.sun_direction = glm::vec3(0.0f, -0.6f, 0.8f);
  ScenarioRunner runner(s, small_headless());
  EXPECT_NEAR(runner.sun().elevation_deg, std::asin(0.8) * 180.0 / M_PI, 1e-4);
  EXPECT_NEAR(runner.sun().azimuth_deg, 180.0, 1e-4);
}

}  // namespace
