// The shading's normal from one read of the DEM's central differences
// (gl::upload_height_differences_texture, shaders/height_differences_texture.frag)
// against four height reads a sample apart (height_differences_heights.frag):
// the same views of a generated terrain give the same picture within the
// differences' half-float rounding; a scene with an overview keeps the four
// reads. Headless EGL on llvmpipe.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "render/frame_renderer.h"
#include "render/terrain_method.h"
#include "session/scenario_runner.h"
#include "session/view_step.h"
#include "view_tour_scenario.h"

namespace {

constexpr int kW = 256, kH = 192;

TEST(HeightDifferences, OneReadGivesThePictureOfFourHeightReads) {
  const std::vector<render_checks::View> views = {
      {"valley", 4000, 3000, 120, 40, -4}, {"ridge", 7600, 7600, 400, 200, -12}, {"skyline", 2500, 9000, 60, 95, 2}};
  auto scenario = render_checks::view_tour_scenario("height_differences_test", views, kW, kH, 45.0);
  scenario.render.antialiasing = "off";
  ig::session::RunOptions o;
  o.method = "reference";
  o.headless = true;
  o.shader_dir = std::string(IG_BIN_DIR) + "/shaders";
  ig::session::ScenarioRunner runner(scenario, o);
  ig::render::TerrainScene& scene = runner.scene();
  ASSERT_TRUE(scene.height_differences_texture()) << "a DEM that fits one texture reads its differences";
  std::vector<ig::render::Camera> cameras;
  for (int f = 0; f < int(views.size()); ++f) {
    runner.render_frame(f);
    cameras.push_back(runner.channels().front().camera);
  }

  for (const std::string method : {"twolevel", "cdlod"}) {
    std::vector<std::vector<std::uint8_t>> pictures[2];
    for (int one_read = 1; one_read >= 0; --one_read) {
      scene.set_height_differences_texture(one_read == 1);  // for the programs made next
      auto m = ig::render::make_method(method, scene, o.shader_dir, runner.scenario().render.method_options());
      ig::render::FrameRenderer renderer(scene, *m, o.shader_dir);
      ig::gl::RenderTarget target(kW, kH);
      for (const auto& camera : cameras) {
        ig::session::render_view(scene, renderer, camera, target);
        pictures[one_read].push_back(target.read_rgba());
      }
    }
    scene.set_height_differences_texture(true);
    for (size_t f = 0; f < cameras.size(); ++f) {
      const auto &one = pictures[1][f], &four = pictures[0][f];
      ASSERT_EQ(one.size(), four.size());
      int worst = 0;
      long long differing = 0;
      for (size_t k = 0; k < one.size(); ++k) {
        const int d = std::abs(int(one[k]) - int(four[k]));
        worst = std::max(worst, d);
        differing += d > 0;
      }
      std::printf("%s view %zu: one read against four: max %d levels, %lld channels differ of %zu\n", method.c_str(),
                  f, worst, differing, one.size());
      EXPECT_LE(worst, 2) << method << " view " << f;
      EXPECT_LT(double(differing), 0.01 * double(one.size())) << method << " view " << f;
    }
  }
}

TEST(HeightDifferences, AnOverviewKeepsTheFourHeightReads) {
  const std::vector<render_checks::View> views = {{"valley", 4000, 3000, 120, 40, -4}};
  auto scenario = render_checks::view_tour_scenario("height_differences_overview", views, 64, 48, 45.0);
  ig::session::RunOptions o;
  o.headless = true;
  o.shader_dir = std::string(IG_BIN_DIR) + "/shaders";
  ig::session::ScenarioRunner runner(scenario, o);  // the GL context
  EXPECT_TRUE(runner.scene().height_differences_texture());
  const ig::render::TerrainScene overview(runner.heightfield(), ig::render::ShadingParams{}, std::nullopt,
                                          /*texture_limit=*/128);
  EXPECT_GT(overview.overview_step(), 1);
  EXPECT_FALSE(overview.height_differences_texture()) << "the overview's heights are not the DEM's";
}

}  // namespace
