// Work counters (issue 13): every method's frame reports shader invocations
// and primitives per pass (pipeline statistics queries on llvmpipe), draw
// calls and bytes uploaded, and they agree with what was drawn.
#include <gtest/gtest.h>

#include <cstdio>

#include "gl/work_counters.h"
#include "session/scenario_runner.h"
#include "io/pose.h"
#include "io/scenario.h"
#include "render/terrain_method.h"
#include "session/view_step.h"

namespace {
using ig::session::RunOptions;
using ig::session::ScenarioRunner;

constexpr int kW = 160, kH = 120;

RunOptions options(const std::string& method) {
  RunOptions o;
  o.width = kW;
  o.height = kH;
  o.headless = true;
  o.shader_dir = std::string(IG_BIN_DIR) + "/shaders";
  o.method = method;
  o.frames = 2;
  return o;
}
}  // namespace

TEST(WorkCounters, PipelineStatisticsAreAvailable) {
  ScenarioRunner runner(ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json"),
                        options("reference"));
  EXPECT_TRUE(ig::gl::PassRecorder::supported()) << runner.context().gl_version();
}

TEST(WorkCounters, EveryMethodCountsItsWork) {
  for (const auto& method : ig::render::method_names()) {
    ScenarioRunner runner(ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json"),
                          options(method));
    runner.render_frame(0);
    runner.render_frame(1);  // two-level's size controller and band have settled in
    const auto& ch = runner.channels().front();
    const auto& v = ch.last;
    const auto depth = ch.target->read_depth();
    long long terrain_px = 0;
    for (float d : depth) terrain_px += d > 0.0f;
    std::printf("[work] %-10s vs %8llu fs %8llu prims %7llu draws %4llu upload %7llu B, triangles %lld, terrain px "
                "%lld, passes:", method.c_str(), (unsigned long long)v.total.vs_invocations,
                (unsigned long long)v.total.fs_invocations, (unsigned long long)v.total.primitives,
                (unsigned long long)v.total.draw_calls, (unsigned long long)v.total.bytes_uploaded,
                v.method.triangles, terrain_px);
    for (const auto& p : v.passes) std::printf(" %s %llu/%llu", p.name.c_str(), (unsigned long long)p.fs_invocations,
                                               (unsigned long long)p.draw_calls);
    std::printf("\n");
    ASSERT_GE(v.passes.size(), 2u);
    // The method's passes, then the sky and the anti-aliasing post pass
    // (two draws when the frame is post-filtered, none otherwise).
    const auto& sky = v.passes[v.passes.size() - 2];
    EXPECT_EQ(sky.name, "sky");
    EXPECT_EQ(v.passes.back().name, "aa");
    EXPECT_EQ(v.passes.back().draw_calls, ch.target->post_pass() ? 2u : 0u) << method;
    EXPECT_GT(v.total.vs_invocations, 0u) << method;
    EXPECT_GT(v.total.draw_calls, 1u) << method;  // terrain and sky at least
    EXPECT_GT(terrain_px, 0) << method;
    // Every covered terrain pixel ran the fragment shader at least once in
    // the terrain passes (more with overdraw and offscreen passes).
    std::uint64_t terrain_fs = 0, sum_draws = 0;
    for (const auto& p : v.passes) {
      if (p.name != "sky" && p.name != "aa") terrain_fs += p.fs_invocations;
      sum_draws += p.draw_calls;
    }
    EXPECT_GE(terrain_fs, std::uint64_t(terrain_px)) << method;
    // The sky: one full-screen triangle, shaded where no terrain is.
    EXPECT_EQ(sky.draw_calls, 1u) << method;
    EXPECT_EQ(sky.primitives, 1u) << method;
    EXPECT_GE(sky.fs_invocations, std::uint64_t(kW * kH - terrain_px)) << method;
    // Drawn after the terrain against the far plane: only the uncovered
    // pixels pass the depth test, the fragments an early-z GPU shades.
    EXPECT_EQ(sky.samples_passed, std::uint64_t(kW * kH - terrain_px)) << method;
    // Every triangle the method says it submitted reached the pipeline.
    EXPECT_GE(v.total.primitives, std::uint64_t(v.method.triangles)) << method;
    EXPECT_EQ(sum_draws, v.total.draw_calls) << method;  // no draw outside a pass
  }
}

// The sky shades only where no terrain is: nothing passes looking straight
// down at the terrain, the sky's own pixels looking at the horizon. Every
// method draws the terrain before the same sky pass.
TEST(WorkCounters, SkyPassesOnlyWhereNoTerrainIs) {
  for (const std::string method : {"twolevel", "reference", "geomipmap"}) {
    auto scenario = ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json");
    scenario.render.antialiasing = "off";  // depth as the passes left it
    ScenarioRunner runner(scenario, options(method));
    runner.render_frame(0);
    auto& ch = runner.channels().front();
    const double heading = ig::io::hpr_from_attitude(ch.camera.attitude).heading_deg;
    for (const double pitch : {-89.0, 0.0}) {
      ig::render::Camera camera = ch.camera;
      camera.attitude = ig::io::attitude_from_hpr({heading, pitch, 0.0});
      ig::render::ViewResult v;
      for (int k = 0; k < 3; ++k) v = ig::session::render_view(runner.scene(), *ch.renderer, camera, *ch.target);  // two-level settles its size
      long long sky_px = 0;
      for (float d : ch.target->read_depth()) sky_px += d == 0.0f;
      const auto& sky = v.passes[v.passes.size() - 2];
      ASSERT_EQ(sky.name, "sky");
      std::printf("[sky] %-10s pitch %5.1f: sky px %lld, passed %llu, rasterized %llu of %d\n", method.c_str(), pitch,
                  sky_px, (unsigned long long)sky.samples_passed, (unsigned long long)sky.fs_invocations, kW * kH);
      if (pitch < 0.0) {
        EXPECT_EQ(sky_px, 0) << method << ": looking down, the terrain should fill the view";
      } else {
        EXPECT_GT(sky_px, kW * kH / 10) << method << ": at the horizon, the sky should show";
        EXPECT_LT(sky_px, kW * kH) << method;
      }
      EXPECT_EQ(sky.samples_passed, std::uint64_t(sky_px)) << method << ", pitch " << pitch;
    }
  }
}

// The post-filtered frame's edge pass, after the sky: two full-screen
// triangles, the first (copy and mark) shading every pixel once, the second
// (the filter) passing the marked pixels alone.
TEST(WorkCounters, PostFilterPassIsCounted) {
  auto scenario = ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json");
  scenario.render.antialiasing = "fxaa";
  ScenarioRunner runner(scenario, options("reference"));
  runner.render_frame(0);
  const auto& v = runner.channels().front().last;
  ASSERT_EQ(v.passes.back().name, "aa");
  EXPECT_EQ(v.passes.back().draw_calls, 2u);
  EXPECT_EQ(v.passes.back().primitives, 2u);
  // (llvmpipe counts a few helper invocations along the triangles' edges,
  // and every rasterized fragment of the second, also those its depth test
  // rejects.)
  EXPECT_GE(v.passes.back().fs_invocations, std::uint64_t(kW * kH));
  EXPECT_LE(v.passes.back().fs_invocations, std::uint64_t(2 * kW * kH * 11 / 10));
  EXPECT_GE(v.passes.back().samples_passed, std::uint64_t(kW * kH));
  EXPECT_LT(v.passes.back().samples_passed, std::uint64_t(2 * kW * kH));
  EXPECT_NE(v.method.passes.find("sky+aa"), std::string::npos) << v.method.passes;
  EXPECT_GT(v.timings.resolve_ms, 0.0);
}

TEST(WorkCounters, PassRecorderRejectsUndeclaredPasses) {
  ScenarioRunner runner(ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json"),
                        options("reference"));
  ig::gl::PassRecorder r({"a"});
  r.begin_frame();
  EXPECT_THROW(r.begin("b"), std::logic_error);
  r.begin("a");
  const auto w = r.read();
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].draw_calls, 0u);
}

// Pass timing: each pass's own wall time lies within the stage that ran it
// (terrain passes and deferred shading in the terrain stage, the sky and the
// post pass in theirs), and timing changes neither the work nor the picture.
TEST(WorkCounters, TimedPassesLieWithinTheirStages) {
  struct Frame {
    ig::render::ViewResult view;
    std::vector<std::uint8_t> rgba;
  };
  auto second_frame = [](const std::string& method, bool timed) {
    auto scenario = ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json");
    scenario.render.antialiasing = "fxaa";
    RunOptions o = options(method);
    o.pass_times = timed;
    ScenarioRunner runner(scenario, o);
    runner.render_frame(0);
    runner.render_frame(1);
    return Frame{runner.channels().front().last, runner.channels().front().target->read_rgba()};
  };
  for (const std::string method : {"twolevel", "cdlod"}) {
    const Frame timed = second_frame(method, true), untimed = second_frame(method, false);
    const auto& t = timed.view;
    ASSERT_EQ(t.passes.size(), untimed.view.passes.size()) << method;
    double terrain_passes_ms = 0.0;
    for (size_t k = 0; k < t.passes.size(); ++k) {
      const auto& p = t.passes[k];
      EXPECT_GE(p.ms, 0.0) << method << " " << p.name;
      EXPECT_EQ(untimed.view.passes[k].ms, -1.0) << method << " " << p.name;
      EXPECT_EQ(p.fs_invocations, untimed.view.passes[k].fs_invocations) << method << " " << p.name;
      EXPECT_EQ(p.samples_passed, untimed.view.passes[k].samples_passed) << method << " " << p.name;
      if (p.name == "sky")
        EXPECT_LE(p.ms, t.timings.sky_ms) << method;
      else if (p.name == "aa")
        EXPECT_LE(p.ms, t.timings.resolve_ms) << method;
      else
        terrain_passes_ms += p.ms;
    }
    EXPECT_GT(terrain_passes_ms, 0.0) << method;
    EXPECT_LE(terrain_passes_ms, t.timings.terrain_ms) << method;
    EXPECT_EQ(timed.rgba, untimed.rgba) << method;
  }
}
