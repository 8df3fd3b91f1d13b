// Horizon culling of Level0 (lod/horizon_culling.h) leaves the picture as it
// was: the two-level method with and without it renders the same frames,
// pixel for pixel (colour and depth), on low, wide views of a rough
// generated terrain where it hides many clusters, with and without Earth
// curvature. It must also hide something (else the test proves nothing).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "render/frame_renderer.h"
#include "render/twolevel_method.h"
#include "session/scenario_runner.h"
#include "stats/image_error.h"
#include "view_tour_scenario.h"

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

void expect_same_frames(bool curved) {
  ig::session::RunOptions o;
  o.method = "reference";
  o.headless = true;
  o.shader_dir = std::string(IG_BIN_DIR) + "/shaders";
  ScenarioRunner runner(scenario(curved), o);
  auto options = runner.scenario().render.twolevel;
  std::unique_ptr<ig::render::TwoLevelMethod> methods[2];
  std::unique_ptr<ig::render::FrameRenderer> renderers[2];
  for (int on = 0; on < 2; ++on) {
    options.horizon_culling = on == 1;
    methods[on] = std::make_unique<ig::render::TwoLevelMethod>(runner.scene(), o.shader_dir, options);
    renderers[on] = std::make_unique<ig::render::FrameRenderer>(runner.scene(), *methods[on], o.shader_dir);
  }
  ig::gl::RenderTarget target(kW, kH);
  long long hidden_total = 0, level0_tris[2] = {0, 0}, level1_tris[2] = {0, 0};
  for (int v = 0; v < kViewCount; ++v) {
    runner.render_frame(v);
    const auto camera = runner.channels().front().camera;
    ig::stats::FrameImage images[2];
    for (int on = 0; on < 2; ++on) {
      for (int k = 0; k < kSettle - 1; ++k) renderers[on]->render(camera, target);
      const auto frame = renderers[on]->render(camera, target);
      images[on] = ig::stats::read_frame_image(target);
      for (const auto& [name, value] : frame.method.columns)
        if (name == "level0_tris") level0_tris[on] += (long long)value;
        else if (name == "level1_tris") level1_tris[on] += (long long)value;
    }
    const int hidden = methods[1]->level0_hidden_clusters(), hidden_blocks = methods[1]->level1_hidden_blocks();
    EXPECT_EQ(methods[0]->level0_hidden_clusters() + methods[0]->level1_hidden_blocks(), 0);
    hidden_total += hidden + hidden_blocks;
    long long differing = 0;
    for (size_t p = 0; p < images[0].depth.size(); ++p)
      if (images[0].depth[p] != images[1].depth[p] || std::memcmp(&images[0].rgba[4 * p], &images[1].rgba[4 * p], 4) != 0)
        ++differing;
    std::printf("%s, %-13s: %d Level0 clusters and %d Level1 blocks hidden, %lld pixels differ\n",
                curved ? "curved" : "flat", kViews[v].name, hidden, hidden_blocks, differing);
    EXPECT_EQ(differing, 0) << kViews[v].name << ": horizon culling changed the picture";
  }
  std::printf("Triangles drawn over the views without / with horizon culling: Level0 %lld / %lld, Level1 %lld / %lld\n",
              level0_tris[0], level0_tris[1], level1_tris[0], level1_tris[1]);
  EXPECT_GT(hidden_total, 0) << "nothing was hidden: the views do not exercise the culling";
  EXPECT_LT(level0_tris[1] + level1_tris[1], level0_tris[0] + level1_tris[0]);
}

TEST(HorizonCullingRender, SamePicturesWithAndWithout) { expect_same_frames(false); }
TEST(HorizonCullingRender, SamePicturesWithAndWithoutOnACurvedEarth) { expect_same_frames(true); }

}  // namespace
