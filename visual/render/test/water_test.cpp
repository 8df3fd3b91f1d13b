// Water as drawn: the shoreline against a supersampled render, the sun's
// glint where the mirror direction puts it (and none at night), waves fixed
// to the terrain yet moving with time, the same water for every LOD method,
// and a scene without water linking none of it. On a generated coast (no
// real DEM needed); the real shores are in water_real_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "picture_checks.h"
#include "water_checks.h"
#include "terrain/test/temp_dir_fixture.h"
#include "water_scene.h"

namespace {

using picture::Shot;
using picture::ShotSpec;
using water_checks::differing;
using water_checks::ShoreError;
using water_checks::without_water;

class Water : public ig::terrain::test::TempDirTest {
 protected:
  Water() : TempDirTest("ig_water_gl_") {}
  void SetUp() override {
    TempDirTest::SetUp();
    dem_ = water_scene::write_coast_dem(dir_);
  }
  std::string dem_;
};

TEST_F(Water, ShorelineIsCloseToSupersampled) {
  const auto s = water_scene::coast_scenario(dem_, 200.0, 128.0, 40.0, 0.0, -5.0, "[-0.4, 0.5, 0.75]");
  const int w = 320, h = 240;
  const Shot ss_with = picture::render(s, 0, ShotSpec{4 * w, 4 * h, "off"});
  const Shot ss_without = picture::render(without_water(s), 0, ShotSpec{4 * w, 4 * h, "off"});
  for (const char* aa : {"fxaa", "off"}) {
    const ShoreError e = water_checks::shore_error(picture::render(s, 0, ShotSpec{w, h, aa}), ss_with, ss_without);
    std::printf("[water shore, generated coast] %s: %lld shore pixels, mean |difference| from 16x SS %.2f levels\n", aa,
                e.pixels, e.mean);
    EXPECT_GT(e.pixels, 150);
    EXPECT_LE(e.mean, 10.0) << aa;
  }
}

// The glitter of the sun on the waves: the luminance-weighted centroid of
// the pixels at least half as bright as the brightest, and their rows.
struct Glint {
  double x = 0.0, y = 0.0, peak = 0.0;
  int top = 0, bottom = 0;  // rows
};
Glint glint_of(const Shot& shot) {
  Glint g;
  for (int y = 0; y < shot.h; ++y)
    for (int x = 0; x < shot.w; ++x) g.peak = std::max(g.peak, picture::luminance(shot, x, y));
  double sx = 0.0, sy = 0.0, sw = 0.0;
  g.top = shot.h;
  for (int y = 0; y < shot.h; ++y)
    for (int x = 0; x < shot.w; ++x) {
      const double l = picture::luminance(shot, x, y);
      if (l < 0.5 * g.peak) continue;
      sx += l * (x + 0.5);
      sy += l * (y + 0.5);
      sw += l;
      g.top = std::min(g.top, y);
      g.bottom = std::max(g.bottom, y);
    }
  g.x = sx / sw;
  g.y = sy / sw;
  return g;
}

// Mean luminance of the 9 x 9 pixels around (x, y).
double luminance_around(const Shot& shot, double x, double y) {
  double sum = 0.0;
  int n = 0;
  for (int v = -4; v <= 4; ++v)
    for (int u = -4; u <= 4; ++u) {
      const int px = int(x) + u, py = int(y) + v;
      if (px < 0 || py < 0 || px >= shot.w || py >= shot.h) continue;
      sum += picture::luminance(shot, px, py);
      ++n;
    }
  return sum / std::max(n, 1);
}

// The pixel a world direction from the eye projects to (x right, y down).
glm::dvec2 project(const ig::render::Camera& camera, const glm::dvec3& dir, int w, int h) {
  const glm::vec4 clip = camera.view_projection() * glm::vec4(glm::vec3(dir), 0.0f);
  return {(clip.x / clip.w * 0.5 + 0.5) * w, (0.5 - clip.y / clip.w * 0.5) * h};
}

// The glitter runs up the vertical through the sun's mirror direction
// (towards the horizon under the sun, where Fresnel grows) and is bright at
// the mirror point itself; it follows the sun round.
TEST_F(Water, GlintLiesWhereTheSunsMirrorDirectionPutsIt) {
  const int w = 320, h = 240;
  for (const double azimuth : {0.0, 12.0}) {
    const double el = 25.0 * M_PI / 180.0, az = azimuth * M_PI / 180.0;
    const glm::dvec3 sun(std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el));
    char sun_text[96];
    std::snprintf(sun_text, sizeof sun_text, "[%.9f, %.9f, %.9f]", sun.x, sun.y, sun.z);
    auto s = water_scene::coast_scenario(dem_, 200.0, 50.0, 150.0, 0.0, -25.0, sun_text, w, h);
    s.render.antialiasing = "off";
    ig::session::ScenarioRunner runner(s, headless_run(w, h));
    runner.render_frame(0);
    const Shot shot{w, h, runner.channels().front().target->read_rgba(), {}, {}};
    const Glint g = glint_of(shot);
    const glm::dvec2 mirror = project(runner.channels().front().camera, {sun.x, sun.y, -sun.z}, w, h);
    const double at_mirror = luminance_around(shot, mirror.x, mirror.y);
    const double beside = 0.5 * (luminance_around(shot, mirror.x - w / 4.0, mirror.y) +
                                 luminance_around(shot, mirror.x + w / 4.0, mirror.y));
    std::printf("[water glint] sun azimuth %.0f, elevation 25: glint centroid %.1f, %.1f (rows %d-%d, peak %.0f); "
                "mirror direction at %.1f, %.1f: luminance there %.0f, a quarter frame beside it %.0f\n",
                azimuth, g.x, g.y, g.top, g.bottom, g.peak, mirror.x, mirror.y, at_mirror, beside);
    EXPECT_GT(g.peak, 200.0);
    EXPECT_NEAR(g.x, mirror.x, 0.03 * w);
    EXPECT_GT(at_mirror, 2.0 * beside);
    EXPECT_GT(at_mirror, 0.3 * g.peak);
  }
}

TEST_F(Water, NoGlintAtNight) {
  const int w = 160, h = 120;
  auto night = water_scene::coast_scenario(dem_, 200.0, 50.0, 150.0, 0.0, -25.0, "[0, 0.9, -0.3]", w, h);
  const Shot shot = picture::render(night, 0, ShotSpec{w, h, "off", true, "twolevel"});
  double peak = 0.0;
  for (int y = h / 2; y < h; ++y)
    for (int x = 0; x < w; ++x) peak = std::max(peak, picture::luminance(shot, x, y));
  std::printf("[water night] brightest water pixel %.1f levels\n", peak);
  EXPECT_LT(peak, 40.0);
}

TEST_F(Water, WavesAreFixedToTheTerrainAndMoveWithTime) {
  const int w = 320, h = 240;
  auto s = water_scene::coast_scenario(dem_, 200.0, 60.0, 30.0, 10.0, -20.0, "[-0.4, 0.5, 0.75]", w, h);
  s.render.antialiasing = "off";
  ig::session::ScenarioRunner runner(s, headless_run(w, h));
  const ig::io::Pose at = runner.pose_at(0.0);
  // Across a sample boundary by 1 mm, at one time: the waves stay put.
  ig::io::Pose a = at, b = at;
  const double x = std::round(at.position.x / runner.heightfield().spacing_x_m) * runner.heightfield().spacing_x_m;
  a.position.x = x - 0.0005;
  b.position.x = x + 0.0005;
  auto shot_at = [&](double t, const ig::io::Pose& p) {
    runner.render_pose(0, t, p);
    return Shot{w, h, runner.channels().front().target->read_rgba(), {}, {}};
  };
  const double still = picture::mean_abs_difference(shot_at(5.0, a), shot_at(5.0, b));
  const double later = picture::mean_abs_difference(shot_at(5.0, a), shot_at(6.0, a));
  std::printf("[water waves] 1 mm across a sample: %.4f levels; 1 s later: %.2f levels\n", still, later);
  EXPECT_LT(still, 0.05);
  EXPECT_GT(later, 1.0);
}

TEST_F(Water, EveryMethodDrawsTheSameWater) {
  const int w = 240, h = 180;
  auto s = water_scene::coast_scenario(dem_, 200.0, 90.0, 120.0, 350.0, -8.0, "[-0.4, 0.5, 0.75]", w, h);
  const Shot reference = picture::render(s, 0, ShotSpec{w, h, "off", true, "reference"});
  const Shot dry = picture::render(without_water(s), 0, ShotSpec{w, h, "off", true, "reference"});
  const std::vector<bool> wet = differing(reference, dry);
  for (const char* method : {"twolevel", "roam", "geomipmap", "chunked", "quadtree", "cdlod"}) {
    const Shot shot = picture::render(s, 0, ShotSpec{w, h, "off", true, method});
    double sum = 0.0;
    long long n = 0;
    for (std::size_t p = 0; p < wet.size(); ++p)
      if (wet[p]) {
        for (int k = 0; k < 3; ++k) sum += std::abs(int(shot.rgba[p * 4 + k]) - int(reference.rgba[p * 4 + k]));
        ++n;
      }
    const double mean = sum / (3.0 * double(std::max(n, 1LL)));
    std::printf("[water methods] %s: %lld water pixels, mean |difference| from the reference %.3f levels\n", method, n,
                mean);
    EXPECT_GT(n, w * h / 4);
    EXPECT_LT(mean, 1.5) << method;
  }
}

bool has(const std::vector<std::string>& stages, const char* stage) {
  return std::find(stages.begin(), stages.end(), stage) != stages.end();
}

// Deferred shading (the default here): the terrain passes shade land alone,
// the shading pass marks where water may be, the water pass draws it.
// Forward shading draws it in the terrain passes. Without water none of it
// is linked or run.
TEST_F(Water, ASceneWithoutWaterLinksNone) {
  auto s = water_scene::coast_scenario(dem_, 200.0, 90.0, 120.0, 350.0, -8.0, "[-0.4, 0.5, 0.75]");
  s.render.antialiasing = "off";
  ig::session::ScenarioRunner with(s, headless_run(64, 48));
  const auto& scene = with.scene();
  ASSERT_TRUE(scene.has_water());
  EXPECT_TRUE(has(scene.shading_stages({}), "water_none.frag"));
  EXPECT_TRUE(has(scene.deferred_shade_stages(), "water_mark.frag"));
  EXPECT_TRUE(has(scene.water_shade_stages(), "water.frag"));
  with.render_frame(0);
  EXPECT_NE(with.channels().front().last.method.passes.find("water"), std::string::npos);

  auto forward = s;
  forward.render.shading.deferred_shading = false;
  ig::session::ScenarioRunner in_pass(forward, headless_run(64, 48));
  EXPECT_TRUE(has(in_pass.scene().shading_stages({}), "water_in_shading.frag"));
  in_pass.render_frame(0);
  EXPECT_EQ(in_pass.channels().front().last.method.passes.find("water"), std::string::npos);

  ig::session::ScenarioRunner without(without_water(s), headless_run(64, 48));
  EXPECT_FALSE(without.scene().has_water());
  EXPECT_FALSE(without.heightfield().water);
  for (const auto& stages : {without.scene().shading_stages({}), without.scene().deferred_shade_stages()}) {
    EXPECT_FALSE(has(stages, "water.frag"));
    EXPECT_FALSE(has(stages, "sky_colour.frag"));
  }
  EXPECT_TRUE(has(without.scene().deferred_shade_stages(), "water_mark_none.frag"));
  EXPECT_TRUE(without.scene().water_shade_stages().empty());
  without.render_frame(0);
  EXPECT_EQ(without.channels().front().last.method.passes.find("water"), std::string::npos);
  for (const auto& p : without.channels().front().last.passes) EXPECT_NE(p.name, "water");
}

// The water pass blends over the 8-bit frame; shading in the terrain pass
// mixes before it is stored: the same picture within that rounding (a few
// levels at a handful of shore pixels; measured 0.008 mean, 4 at most).
TEST_F(Water, DeferredAndForwardShadingDrawTheSameWater) {
  const int w = 240, h = 180;
  auto s = water_scene::coast_scenario(dem_, 200.0, 90.0, 120.0, 350.0, -8.0, "[-0.4, 0.5, 0.75]", w, h);
  const Shot deferred = picture::render(s, 0, ShotSpec{w, h, "off", true, "twolevel"});
  s.render.shading.deferred_shading = false;
  const Shot forward = picture::render(s, 0, ShotSpec{w, h, "off", true, "twolevel"});
  int worst = 0;
  for (std::size_t k = 0; k < deferred.rgba.size(); ++k)
    worst = std::max(worst, std::abs(int(deferred.rgba[k]) - int(forward.rgba[k])));
  const double mean = picture::mean_abs_difference(deferred, forward);
  std::printf("[water deferred vs forward] mean |difference| %.4f, largest %d levels\n", mean, worst);
  EXPECT_LE(worst, 6);
  EXPECT_LT(mean, 0.05);
}

}  // namespace
