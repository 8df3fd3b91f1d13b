// Image tests of the reference renderer on the default scenario's flight, headless
// (EGL on llvmpipe), small frames.
#include <gtest/gtest.h>

#include <cmath>

#include "io/scenario.h"
#include "render/test/headless_run.h"
#include "session/scenario_runner.h"
#include "terrain/height_pyramid.h"
#include "terrain/ray_cast.h"

namespace {

using ig::session::RunOptions;
using ig::session::ScenarioRunner;

constexpr int kW = 320, kH = 240;

ig::io::Scenario default_scenario() {
  return ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json");
}

RunOptions small_headless() {
  return headless_run(kW, kH, "reference");  // these tests are about the reference renderer
}

TEST(DefaultScenario, FirstFrameHasSkyAboveAndTerrainBelow) {
  ScenarioRunner runner(default_scenario(), small_headless());
  runner.render_frame(0);
  const auto& target = *runner.channels().front().target;
  const auto depth = target.read_depth();
  const auto rgba = target.read_rgba();
  EXPECT_NE(runner.context().gl_version().find("4.5"), std::string::npos) << runner.context().gl_version();

  // Bottom 30 % of rows: terrain (depth > 0); the top row: mostly sky (depth
  // cleared to 0; the tallest peaks may reach into it); no black pixels.
  int sky_top = 0, terrain_bottom = 0, black = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const size_t p = size_t(y) * kW + x;
      ASSERT_TRUE(std::isfinite(depth[p])) << "depth NaN at " << x << "," << y;
      if (y == 0) sky_top += depth[p] == 0.0f;
      if (y >= kH * 7 / 10) terrain_bottom += depth[p] > 0.0f;
      const int sum = rgba[p * 4] + rgba[p * 4 + 1] + rgba[p * 4 + 2];
      black += sum < 12;
    }
  EXPECT_GT(sky_top, kW / 2) << "the top row should be mostly sky";
  EXPECT_EQ(terrain_bottom, kW * (kH - kH * 7 / 10)) << "every bottom-row pixel should be terrain";
  EXPECT_EQ(black, 0) << "black pixels mean holes or NaN shading";

  // Sky exactly where the exact ray cast misses the terrain, terrain where it
  // hits (pixels on a silhouette may go either way: allow 1 %).
  const ig::terrain::HeightPyramid pyramid(runner.heightfield());
  const auto& cam = runner.channels().front().camera;
  int samples = 0, disagree = 0;
  for (int y = 0; y < kH; y += 3)
    for (int x = 0; x < kW; x += 3) {
      const bool hit = ig::terrain::cast_ray(runner.heightfield(), pyramid, cam.position,
                                             cam.pixel_ray(x, y, kW, kH)).has_value();
      disagree += hit != (depth[size_t(y) * kW + x] > 0.0f);
      ++samples;
    }
  EXPECT_LE(disagree, samples / 100) << disagree << " of " << samples << " pixels disagree with the ray cast";
  // The sky is bluer than it is red; terrain pixels are not sky-coloured.
  const size_t top = size_t(2) * kW + kW / 2;
  EXPECT_GT(rgba[top * 4 + 2], rgba[top * 4]);
}

TEST(DefaultScenario, TwoRunsArePixelIdentical) {
  std::vector<std::uint8_t> first, second;
  for (auto* out : {&first, &second}) {
    ScenarioRunner runner(default_scenario(), small_headless());
    runner.render_frame(0);
    runner.render_frame(37);
    *out = runner.channels().front().target->read_rgba();
  }
  ASSERT_EQ(first.size(), second.size());
  EXPECT_TRUE(first == second) << "replay must be deterministic";
}

TEST(DefaultScenario, DepthBufferAgreesWithExactRayCast) {
  // The rendered depth at a pixel and the exact ray cast through that pixel
  // must find the same surface: camera, projection, reversed-Z and mesh agree.
  // Single-sampled: a multisampled frame's resolved depth is one of the
  // pixel's samples, not the depth at its centre where the ray goes.
  auto scenario = default_scenario();
  scenario.render.antialiasing = "off";
  ScenarioRunner runner(scenario, small_headless());
  runner.render_frame(0);
  auto& ch = runner.channels().front();
  const auto depth = ch.target->read_depth();
  const ig::terrain::HeightPyramid pyramid(runner.heightfield());
  int checked = 0;
  for (int y = kH / 2; y < kH; y += 17)
    for (int x = 5; x < kW; x += 31) {
      const float d = depth[size_t(y) * kW + x];
      if (d <= 0.0f) continue;
      const glm::dvec3 dir = ch.camera.pixel_ray(x, y, kW, kH);
      const auto hit = ig::terrain::cast_ray(runner.heightfield(), pyramid, ch.camera.position, dir);
      ASSERT_TRUE(hit.has_value()) << "pixel " << x << "," << y << " shows terrain but the ray misses";
      const double along_axis = hit->t * glm::dot(dir, ch.camera.forward());
      const double rendered = ch.camera.depth_to_view_distance(d);
      EXPECT_NEAR(rendered, along_axis, 1e-3 * along_axis + 0.5) << "pixel " << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 20);
}

TEST(DefaultScenario, EveryFrameOfTheRunIsLogged) {
  auto s = default_scenario();
  RunOptions o = small_headless();
  o.frames = 3;
  ScenarioRunner runner(s, o);
  EXPECT_EQ(runner.frame_count(), 3);
  for (int k = 0; k < runner.frame_count(); ++k) {
    const auto f = runner.render_frame(k);
    const auto row = ig::session::frame_log_row(f, runner.channels().front(), 0.0, 0.0);
    ASSERT_GE(row.size(), 10u);
    EXPECT_EQ(row[0].name, "frame");
    EXPECT_EQ(row[0].text, std::to_string(k));
    EXPECT_GT(runner.channels().front().last.method.triangles, 0);
    // (+shade: deferred shading, the default; +aa: the post-filter pass,
    // when the frame is post-filtered)
    EXPECT_EQ(runner.channels().front().last.method.passes,
              runner.channels().front().target->post_pass() ? "terrain+shade+sky+aa" : "terrain+sky");
  }
}

}  // namespace
