// The temporal error (stats/temporal_error.h, ig bench's popping measure) on
// real renders: a method whose mesh changes abruptly between two consecutive
// frames scores worse than the same method whose mesh does not, while the
// camera moves a little between the frames as in flight.
//
// The abrupt change is GeoMipMapping's error knob jumping from its coarsest
// sweep value to a fine one between the frames (what a LOD switch without
// morphing does to many blocks at once): the earlier frame is drawn by the
// coarse instance, the later one by the fine instance. The steady method
// draws both frames with the fine instance, so the later images are the same
// and only the earlier frame's mesh differs. Headless EGL on llvmpipe, a
// generated terrain (view_tour_scenario.h).
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

#include "render/frame_renderer.h"
#include "render/terrain_method.h"
#include "session/scenario_runner.h"
#include "stats/temporal_error.h"
#include "view_tour_scenario.h"
#include "session/view_step.h"

namespace {

constexpr int kW = 256, kH = 192;

ig::stats::LumaImage luma_of(const ig::gl::RenderTarget& target) {
  return ig::stats::luminance(ig::stats::read_frame_image(target));
}

TEST(Popping, AMeshThatChangesAbruptlyBetweenFramesScoresWorseThanASteadyOne) {
  // Two frames 0.5 s apart at about 120 m/s, low over rough terrain.
  const std::vector<render_checks::View> views = {{"before", 4000, 3000, 200, 40, -6},
                                                  {"after", 4040, 3045, 200, 40.5, -6}};
  auto scenario = render_checks::view_tour_scenario("popping_test", views, kW, kH, 45.0);
  scenario.render.shading.fog_visibility_m = 30000.0;
  ig::session::RunOptions o;
  o.method = "reference";
  o.headless = true;
  o.shader_dir = std::string(IG_BIN_DIR) + "/shaders";
  ig::session::ScenarioRunner runner(scenario, o);
  auto& channel = runner.channels().front();
  ig::stats::LumaImage ref[2];
  ig::render::Camera camera[2];
  for (int f = 0; f < 2; ++f) {
    runner.render_frame(f);
    ref[f] = luma_of(*channel.target);
    camera[f] = channel.camera;
  }

  const auto sweep = ig::render::knob_sweep("geomipmap");
  ASSERT_GE(sweep.size(), 2u);
  const double coarse = sweep.front(), fine = sweep.back();  // least to most accurate
  const auto options = runner.scenario().render.method_options();
  auto make = [&](double knob) {
    return ig::render::make_method("geomipmap", runner.scene(), o.shader_dir, options, knob);
  };
  auto coarse_method = make(coarse), fine_method = make(fine);
  ig::render::FrameRenderer coarse_renderer(runner.scene(), *coarse_method, o.shader_dir);
  ig::render::FrameRenderer fine_renderer(runner.scene(), *fine_method, o.shader_dir);
  ig::gl::RenderTarget target(kW, kH);

  const long long coarse_triangles = ig::session::render_view(runner.scene(), coarse_renderer, camera[0], target).method.triangles;
  const auto coarse_before = luma_of(target);
  const long long fine_triangles = ig::session::render_view(runner.scene(), fine_renderer, camera[0], target).method.triangles;
  const auto fine_before = luma_of(target);
  ig::session::render_view(runner.scene(), fine_renderer, camera[1], target);
  const auto fine_after = luma_of(target);
  ASSERT_LT(coarse_triangles, fine_triangles) << "the knob jump should change the mesh";

  const auto steady = ig::stats::temporal_error(fine_before, fine_after, ref[0], ref[1]);
  const auto popping = ig::stats::temporal_error(coarse_before, fine_after, ref[0], ref[1]);
  std::printf("tau_px %g -> %g: temporal error %.3f (method change %.3f), steady tau_px %g: %.3f (method change "
              "%.3f); reference change %.3f luma levels; %lld -> %lld triangles\n",
              coarse, fine, popping.mean, popping.method_change, fine, steady.mean, steady.method_change,
              steady.reference_change, coarse_triangles, fine_triangles);
  ASSERT_GT(steady.reference_change, 0.0) << "the camera should move between the frames";
  EXPECT_GT(popping.mean, steady.mean) << "the knob jump should show as popping";
}

}  // namespace
