// Cloud layers measured on real frames of the default scenario (its
// generated terrain is placed at 46.5 N, 7.9 E) at noon on midsummer's day,
// rendered headless and read back. What shows of the sky is judged against
// the same frame without clouds (a clear-sky pixel keeps at least half of
// the sky's blue over red); what shows of the terrain against two frames
// whose terrain is draped red and blue: the share of that difference left
// is the share of the terrain that reaches the eye.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <cstdio>
#include <string>
#include <vector>

#include "capture/png_writer.h"
#include "io/scenario.h"
#include "io/utc_time.h"
#include "render/test/headless_run.h"
#include "session/scenario_runner.h"
#include "terrain/heightfield.h"

namespace {

using ig::options::CloudLayer;
using ig::options::CloudLayers;
using ig::options::CloudType;
using ig::session::ScenarioRunner;

constexpr int kW = 256, kH = 192;
constexpr const char* kNoon = "2026-06-21T11:30:00Z";

struct View {
  double x = 15000.0, y = 15000.0, z = 2500.0;  // terrain-local metres, above sea level
  double heading_deg = 0.0, pitch_deg = 0.0;
  double fov_y_deg = 60.0;
};

ig::io::Scenario scene(const View& v, const CloudLayers& clouds, const std::string& time_utc = kNoon) {
  auto s = ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json");
  s.render.shading.sun_direction.reset();
  std::string why;
  s.render.shading.time_utc = ig::io::parse_utc_time(time_utc, why);
  s.render.shading.clouds = clouds;
  s.render.fov_y_deg = v.fov_y_deg;
  s.path.frame = ig::io::PositionFrame::Local;
  s.path.altitude = ig::io::AltitudeMode::AboveSeaLevel;
  s.path.keys = {ig::io::PathKey{0.0, {v.x, v.y, v.z}, v.heading_deg, v.pitch_deg, 0.0}};
  return s;
}

struct Shot {
  std::vector<std::uint8_t> rgba;
  std::vector<float> depth;
  ig::render::Camera camera;
  std::string passes;
  std::vector<std::string> pass_names;
};

Shot shoot(const ig::io::Scenario& s, const std::string& method = "") {
  ScenarioRunner runner(s, headless_run(kW, kH, method));
  runner.render_frame(0);
  auto& ch = runner.channels().front();
  Shot out{ch.target->read_rgba(), ch.target->read_depth(), ch.camera, ch.last.method.passes, {}};
  for (const auto& p : ch.last.passes) out.pass_names.push_back(p.name);
  return out;
}

CloudLayer layer(CloudType type, double coverage, double base_m, double thickness_m, double visibility_m = 0.0) {
  CloudLayer l;
  l.type = type;
  l.coverage = coverage;
  l.base_m = base_m;
  l.thickness_m = thickness_m;
  l.visibility_m = visibility_m;
  return l;
}

double blue_over_red(const Shot& s, std::size_t p) { return double(s.rgba[4 * p + 2]) - double(s.rgba[4 * p]); }

// Share of the frame that is clear sky: no terrain, and at least half the
// blue over red the cloudless frame has there.
double clear_sky(const Shot& clouds, const Shot& clear) {
  std::size_t n = 0;
  for (std::size_t p = 0; p < std::size_t(kW) * kH; ++p)
    if (clouds.depth[p] == 0.0f && clear.depth[p] == 0.0f && blue_over_red(clear, p) > 20.0 &&
        blue_over_red(clouds, p) >= 0.5 * blue_over_red(clear, p))
      ++n;
  return double(n) / double(kW * kH);
}

// Two single-colour drapes (ground detail off: the colour alone).
std::string drape(const std::string& name, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  const std::string path = std::string(IG_BIN_DIR) + "/../test-out/clouds_" + name + ".png";
  std::vector<std::uint8_t> px;
  for (int i = 0; i < 32 * 32; ++i) px.insert(px.end(), {r, g, b, 255});
  ig::capture::write_png_rgba(path, px, 32, 32);
  return path;
}

// Per pixel, the share of the terrain's colour that reaches the eye (terrain
// pixels of the cloudless frames only; -1 elsewhere).
std::vector<double> terrain_shows(const View& v, const CloudLayers& clouds) {
  auto shot_with = [&](const CloudLayers& c, const std::string& imagery) {
    auto s = scene(v, c);
    s.render.imagery = imagery;
    s.render.shading.ground_detail = false;
    return shoot(s);
  };
  const std::string red = drape("red", 220, 30, 30), blue = drape("blue", 30, 30, 220);
  const Shot a = shot_with(clouds, red), b = shot_with(clouds, blue);
  const Shot a0 = shot_with({}, red), b0 = shot_with({}, blue);
  std::vector<double> share(std::size_t(kW) * kH, -1.0);
  for (std::size_t p = 0; p < share.size(); ++p) {
    if (a0.depth[p] == 0.0f) continue;
    double d = 0.0, d0 = 0.0;
    for (int c = 0; c < 3; ++c) {
      d += std::abs(double(a.rgba[4 * p + c]) - double(b.rgba[4 * p + c]));
      d0 += std::abs(double(a0.rgba[4 * p + c]) - double(b0.rgba[4 * p + c]));
    }
    if (d0 > 120.0) share[p] = d / d0;  // well lit: 8-bit rounding is under 3 % of it
  }
  return share;
}

TEST(Clouds, OvercastHidesTheSkyOverhead) {
  const View up{15000.0, 15000.0, 2500.0, 0.0, 90.0};
  const Shot clear = shoot(scene(up, {}));
  const Shot overcast = shoot(scene(up, {layer(CloudType::Stratus, 1.0, 4000.0, 400.0)}));
  const double without = clear_sky(clear, clear), with = clear_sky(overcast, clear);
  std::printf("looking up, stratus 100 %% 1500 m above: clear sky %.4f (without clouds %.4f)\n", with, without);
  EXPECT_GT(without, 0.95);
  EXPECT_LT(with, 0.02);
  EXPECT_NE(overcast.passes.find("clouds"), std::string::npos) << overcast.passes;
}

TEST(Clouds, CumulusCoverageIsTheShareOfSkyTheyHide) {
  // Three places, each looking straight up 1 500 m under the cumulus base.
  for (const double x : {9000.0, 15000.0, 21000.0}) {
    const View up{x, 15000.0, 2500.0, 0.0, 90.0, 75.0};
    const Shot clear = shoot(scene(up, {}));
    const double half = clear_sky(shoot(scene(up, {layer(CloudType::Cumulus, 0.5, 4000.0, 600.0)})), clear);
    const double quarter = clear_sky(shoot(scene(up, {layer(CloudType::Cumulus, 0.25, 4000.0, 600.0)})), clear);
    std::printf("x %.0f m: clear sky under cumulus 50 %%: %.3f, 25 %%: %.3f\n", x, half, quarter);
    EXPECT_GE(half, 0.35);
    EXPECT_LE(half, 0.65);
    EXPECT_GE(quarter, 0.6);
    EXPECT_LE(quarter, 0.9);
  }
}

TEST(Clouds, DeckBelowHidesTheGround) {
  // 2 000 m above the top of a 100 % deck, looking straight down.
  const View down{15000.0, 15000.0, 2900.0 + 2000.0, 0.0, -90.0};
  const auto share = terrain_shows(down, {layer(CloudType::Stratus, 1.0, 2500.0, 400.0)});
  std::size_t terrain = 0, hidden = 0;
  for (double s : share) {
    if (s < 0.0) continue;
    ++terrain;
    if (s < 0.05) ++hidden;
  }
  const double cloud = double(hidden) / double(kW * kH);
  std::printf("2 000 m above a 100 %% deck looking down: %.4f of the frame is cloud (terrain in %zu px)\n", cloud,
              terrain);
  EXPECT_GT(cloud, 0.95);
}

// Pixels whose terrain lies 0.9 to 1.1 km from the eye in a cloudless frame,
// as do their eight neighbours' (the anti-aliasing blends a pixel with its
// neighbours: a nearer hill's edge would carry nearer terrain into it).
std::vector<std::size_t> ridge_pixels(const Shot& clear) {
  std::vector<double> distance(std::size_t(kW) * kH, -1.0);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const std::size_t p = std::size_t(y) * kW + x;
      if (clear.depth[p] == 0.0f) continue;
      const glm::dvec3 ray = clear.camera.pixel_ray(x + 0.5, y + 0.5, kW, kH);
      distance[p] = clear.camera.depth_to_view_distance(clear.depth[p]) / glm::dot(ray, clear.camera.forward());
    }
  std::vector<std::size_t> out;
  for (int y = 1; y + 1 < kH; ++y)
    for (int x = 1; x + 1 < kW; ++x) {
      bool all = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const double d = distance[std::size_t(y + dy) * kW + (x + dx)];
          all = all && d >= 900.0 && d <= 1100.0;
        }
      if (all) out.push_back(std::size_t(y) * kW + x);
    }
  return out;
}

TEST(Clouds, InsideALayerItsVisibilityHidesARidgeAKilometreAway) {
  // The eye 30 m over the ground, looking a little down, turned until the
  // cloudless frame has terrain 0.9-1.1 km away.
  const auto s0 = scene(View{}, {});
  ScenarioRunner probe(s0, headless_run(16, 16));
  const auto& hf = probe.heightfield();
  const double x = 15000.0, y = 15000.0;
  const double eye = hf.at(int(x / hf.spacing_x_m), int(y / hf.spacing_y_m)) + 30.0;
  View view;
  Shot clear;
  std::vector<std::size_t> ridge;
  for (double heading = 0.0; heading < 360.0 && ridge.size() < 200; heading += 45.0) {
    view = View{x, y, eye, heading, -3.0, 30.0};
    clear = shoot(scene(view, {}));
    ridge = ridge_pixels(clear);
  }
  ASSERT_GE(ridge.size(), std::size_t(200)) << "no view of terrain 1 km away from the test's place";
  // A stratus layer of visibility 500 m from the ground to 300 m over the
  // eye; then the same layer lifted above the eye.
  const double ground = double(hf.min_m);
  const CloudLayer inside = layer(CloudType::Stratus, 1.0, ground, eye + 300.0 - ground, 500.0);
  CloudLayer above = inside;
  above.base_m = eye + 200.0;
  above.thickness_m = 300.0;
  auto ridge_share = [&](const CloudLayers& clouds) {
    const auto share = terrain_shows(view, clouds);
    double most = 0.0, sum = 0.0;
    std::size_t n = 0;
    for (std::size_t p : ridge) {
      if (share[p] < 0.0) continue;
      most = std::max(most, share[p]);
      sum += share[p];
      ++n;
    }
    return std::pair(most, n ? sum / double(n) : -1.0);
  };
  const auto [in_most, in_mean] = ridge_share({inside});
  const auto [out_most, out_mean] = ridge_share({above});
  std::printf("terrain 0.9-1.1 km away (%zu px, heading %.0f): inside a 500 m visibility layer it shows %.4f "
              "(most %.4f); under the layer %.3f\n", ridge.size(), view.heading_deg, in_mean, in_most, out_mean);
  EXPECT_GE(in_mean, 0.0);
  EXPECT_LT(in_most, 0.02);  // Koschmieder: exp(-3.912 * 1000 / 500) = 0.0004
  EXPECT_GT(out_mean, 0.9);  // the fog in force (45 km) takes under 1 % at 1 km
}

TEST(Clouds, EveryMethodDrawsTheSameClouds) {
  // Under scattered cumulus looking at the horizon: the clouds are one pass
  // over whatever terrain a method drew, so the sky each shows is the same.
  const View v{15000.0, 15000.0, 2400.0, 30.0, 8.0};
  const CloudLayers cu{layer(CloudType::Cumulus, 0.5, 3000.0, 600.0)};
  const Shot clear = shoot(scene(v, {}), "twolevel");
  const double reference = clear_sky(shoot(scene(v, cu), "twolevel"), clear);
  for (const char* method : {"reference", "roam", "geomipmap", "chunked", "quadtree", "cdlod"}) {
    const Shot m_clear = shoot(scene(v, {}), method);
    const double m = clear_sky(shoot(scene(v, cu), method), m_clear);
    std::printf("%s: clear sky %.4f (twolevel %.4f)\n", method, m, reference);
    EXPECT_NEAR(m, reference, 0.01) << method;
  }
}

// Mean luma (8-bit levels) of the pixels a layer changes.
double cloud_luma(const Shot& clouds, const Shot& clear) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t p = 0; p < std::size_t(kW) * kH; ++p) {
    double diff = 0.0;
    for (int c = 0; c < 3; ++c) diff += std::abs(double(clouds.rgba[4 * p + c]) - double(clear.rgba[4 * p + c]));
    if (diff < 30.0) continue;
    sum += 0.2126 * clouds.rgba[4 * p] + 0.7152 * clouds.rgba[4 * p + 1] + 0.0722 * clouds.rgba[4 * p + 2];
    ++n;
  }
  return n ? sum / double(n) : -1.0;
}

TEST(Clouds, LitByTheSunAndSkyFromNoonToMidnight) {
  const View v{15000.0, 15000.0, 2400.0, 30.0, 20.0};
  const CloudLayers cu{layer(CloudType::Cumulus, 0.5, 3000.0, 600.0)};
  double luma[3];
  const char* times[3] = {kNoon, "2026-06-21T19:45:00Z", "2026-12-21T23:00:00Z"};
  for (int k = 0; k < 3; ++k) luma[k] = cloud_luma(shoot(scene(v, cu, times[k])), shoot(scene(v, {}, times[k])));
  std::printf("cloud luma: noon %.1f, dusk %.1f, midnight %.1f\n", luma[0], luma[1], luma[2]);
  EXPECT_GT(luma[0], 120.0);
  EXPECT_LT(luma[1], luma[0]);
  EXPECT_GE(luma[2], 0.0);  // the clouds changed pixels at midnight too
  EXPECT_LT(luma[2], 30.0);  // no glowing clouds at night
}

TEST(Clouds, FixedToTheWorldAsTheEyeTurns) {
  // Straight up, heading 0 and 180: the same sky turned half a turn, so
  // pixel (x, y) of one is pixel (w-1-x, h-1-y) of the other, within the
  // half-resolution pixel the march may shift an edge by (the 5 x 5 frame
  // pixels around it) and the few levels its upsampling may change.
  const CloudLayers st{layer(CloudType::Stratus, 0.5, 6000.0, 300.0)};
  const Shot a = shoot(scene(View{15000.0, 15000.0, 2500.0, 0.0, 90.0, 90.0}, st));
  const Shot b = shoot(scene(View{15000.0, 15000.0, 2500.0, 180.0, 90.0, 90.0}, st));
  std::size_t off = 0, cloud = 0;
  double sum = 0.0;
  const Shot clear = shoot(scene(View{15000.0, 15000.0, 2500.0, 0.0, 90.0, 90.0}, {}));
  for (int y = 2; y + 2 < kH; ++y)
    for (int x = 2; x + 2 < kW; ++x) {
      const std::size_t p = std::size_t(y) * kW + x;
      int nearest = 256;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
          const std::size_t q = std::size_t(kH - 1 - y + dy) * kW + (kW - 1 - x + dx);
          int most = 0;
          for (int c = 0; c < 3; ++c) most = std::max(most, std::abs(int(a.rgba[4 * p + c]) - int(b.rgba[4 * q + c])));
          nearest = std::min(nearest, most);
        }
      sum += nearest;
      if (nearest > 10) ++off;
      if (blue_over_red(a, p) < 0.5 * blue_over_red(clear, p)) ++cloud;
    }
  const double mean = sum / double((kW - 4) * (kH - 4));
  std::printf("turned half a turn: %zu of %d pixels differ by more than 10 levels from all of their 5 x 5, "
              "%.2f levels on average (cloud in %zu)\n", off, kW * kH, mean, cloud);
  EXPECT_GT(cloud, std::size_t(kW * kH / 5));  // there are clouds to compare
  // Only along edges, where a thin lit rim can fall between the march's
  // samples in one frame and on one in the other (0.4 % of the frame here).
  EXPECT_LT(off, std::size_t(kW * kH / 100));
  EXPECT_LT(mean, 1.0);
}

TEST(Clouds, OvercastShadesTheGroundAndNoCloudsCostNothing) {
  const View v{15000.0, 15000.0, 2300.0, 30.0, -20.0};
  const Shot clear = shoot(scene(v, {}));
  const Shot overcast = shoot(scene(v, {layer(CloudType::Stratus, 1.0, 3000.0, 400.0)}));
  double lit = 0.0, shaded = 0.0;
  std::size_t n = 0;
  for (std::size_t p = 0; p < std::size_t(kW) * kH; ++p) {
    if (clear.depth[p] == 0.0f) continue;
    lit += clear.rgba[4 * p + 1];
    shaded += overcast.rgba[4 * p + 1];
    ++n;
  }
  std::printf("terrain under an overcast: %.3f of its sunlit green level\n", shaded / lit);
  ASSERT_GT(n, std::size_t(kW * kH / 2));
  EXPECT_LT(shaded / lit, 0.85);
  EXPECT_GT(shaded / lit, 0.3);  // the diffuse light through the deck remains
  // Without clouds there is no cloud pass at all.
  EXPECT_EQ(clear.passes.find("clouds"), std::string::npos) << clear.passes;
  for (const auto& name : clear.pass_names) EXPECT_NE(name, "clouds");
  EXPECT_EQ(std::count(overcast.pass_names.begin(), overcast.pass_names.end(), "clouds"), 1);
}

TEST(Clouds, AHostsLayersBeyondTheLimitOrUnderTheTerrainAreRefused) {
  ScenarioRunner runner(scene(View{15000.0, 15000.0, 2500.0, 0.0, 90.0}, {}), headless_run(kW, kH));
  CloudLayers many;
  for (int id = 0; id < 256; ++id) {
    CloudLayer l = layer(CloudType::Stratus, 1.0, 4000.0 + 10.0 * id, 5.0);
    l.id = id;
    many.push_back(l);
  }
  many[3].base_m = 0.0;  // 0-5 m: under the terrain (its lowest point is 200 m)
  const auto refused = runner.scene().set_clouds(many);
  ASSERT_EQ(refused.size(), 252u);
  EXPECT_EQ(refused.front(), "cloud layer 3: entirely below the terrain");
  EXPECT_EQ(refused.back(), "cloud layer 255: more than 4 cloud layers");
  ASSERT_EQ(runner.scene().clouds().size(), 4u);
  EXPECT_EQ(runner.scene().clouds()[3].id, 4);
  runner.render_frame(0);
  EXPECT_NE(runner.channels().front().last.method.passes.find("clouds"), std::string::npos);
  // And back to none: the pass goes with them.
  EXPECT_TRUE(runner.scene().set_clouds({}).empty());
  runner.render_frame(0);
  EXPECT_EQ(runner.channels().front().last.method.passes.find("clouds"), std::string::npos);
}

TEST(Clouds, AScenarioLayerUnderTheTerrainIsAnError) {
  try {
    ScenarioRunner runner(scene(View{}, {layer(CloudType::Stratus, 1.0, 0.0, 50.0)}), headless_run(kW, kH));
    FAIL() << "accepted a layer under the terrain";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("environment.clouds: cloud layer 1: entirely below the terrain"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
