// Horizon culling (lod/horizon_culling.h; lod/drawn_surface_occlusion.h for
// the baselines) leaves the picture as it was: every method with and without
// it renders the same frames, pixel for pixel (colour and depth), on low,
// wide views of a rough generated terrain where it hides many pieces, with
// and without Earth curvature. It must also hide something (else the test
// proves nothing) and draw fewer triangles.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "render/frame_renderer.h"
#include "render/terrain_method.h"
#include "session/scenario_runner.h"
#include "stats/image_error.h"
#include "view_tour_scenario.h"
#include "session/view_step.h"

namespace {

using ig::io::Scenario;
using ig::session::ScenarioRunner;

constexpr int kW = 320, kH = 240, kSettle = 4;

using render_checks::View;
const std::vector<View> kViews = {
    {"valley floor", 4000, 3000, 40, 40, 0},       {"low cruise", 7000, 7000, 150, 200, -3},
    {"ridge line", 9000, 4000, 300, 300, -8},      {"climbing", 5000, 9000, 80, 120, 6},
    {"pitched down", 8000, 5000, 500, 10, -30},
};
const int kViewCount = int(kViews.size());

Scenario scenario(bool curved) {
  Scenario s = render_checks::view_tour_scenario("horizon_culling_render_test", kViews, kW, kH, 60.0);
  s.render.earth_curvature = curved ? "on" : "off";
  return s;
}

void expect_same_frames(const std::string& method, bool curved) {
  ig::session::RunOptions o;
  o.method = "reference";
  o.headless = true;
  o.shader_dir = std::string(IG_BIN_DIR) + "/shaders";
  ScenarioRunner runner(scenario(curved), o);
  auto options = runner.scenario().render.method_options();
  std::unique_ptr<ig::render::TerrainMethod> methods[2];
  std::unique_ptr<ig::render::FrameRenderer> renderers[2];
  for (int on = 0; on < 2; ++on) {
    options.set_horizon_culling(on == 1);
    methods[on] = ig::render::make_method(method, runner.scene(), o.shader_dir, options);
    renderers[on] = std::make_unique<ig::render::FrameRenderer>(runner.scene(), *methods[on], o.shader_dir);
  }
  ig::gl::RenderTarget target(kW, kH);
  long long hidden_total = 0, triangles[2] = {0, 0};
  for (int v = 0; v < kViewCount; ++v) {
    runner.render_frame(v);
    const auto camera = runner.channels().front().camera;
    ig::stats::FrameImage images[2];
    double hidden[2] = {0, 0};
    for (int on = 0; on < 2; ++on) {
      for (int k = 0; k < kSettle - 1; ++k) ig::session::render_view(runner.scene(), *renderers[on], camera, target);
      const auto frame = ig::session::render_view(runner.scene(), *renderers[on], camera, target);
      images[on] = ig::stats::read_frame_image(target);
      triangles[on] += frame.method.triangles;
      hidden[on] = frame.method.column("hidden_boxes");
    }
    EXPECT_EQ(hidden[0], 0.0) << "culling off hid something";
    hidden_total += (long long)hidden[1];
    long long differing = 0;
    for (size_t p = 0; p < images[0].depth.size(); ++p)
      if (images[0].depth[p] != images[1].depth[p] || std::memcmp(&images[0].rgba[4 * p], &images[1].rgba[4 * p], 4) != 0)
        ++differing;
    std::printf("%s, %s, %-13s: %.0f boxes hidden, %lld pixels differ\n", method.c_str(), curved ? "curved" : "flat",
                kViews[v].name, hidden[1], differing);
    EXPECT_EQ(differing, 0) << method << ", " << kViews[v].name << ": horizon culling changed the picture";
  }
  std::printf("%s: triangles drawn over the views without / with horizon culling: %lld / %lld\n", method.c_str(),
              triangles[0], triangles[1]);
  EXPECT_GT(hidden_total, 0) << method << ": nothing was hidden: the views do not exercise the culling";
  EXPECT_LT(triangles[1], triangles[0]) << method;
}

class HorizonCullingRender : public ::testing::TestWithParam<std::string> {};

TEST_P(HorizonCullingRender, SamePicturesWithAndWithout) { expect_same_frames(GetParam(), false); }
TEST_P(HorizonCullingRender, SamePicturesWithAndWithoutOnACurvedEarth) { expect_same_frames(GetParam(), true); }

INSTANTIATE_TEST_SUITE_P(EveryMethod, HorizonCullingRender,
                         ::testing::Values("twolevel", "roam", "quadtree", "geomipmap", "chunked", "cdlod"));

}  // namespace
