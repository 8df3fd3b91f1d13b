// Deferred shading (render.deferred_shading, shaders/shade_deferred.frag)
// against shading in the terrain passes: the same views of a generated
// terrain drawn both ways by every method must give the same depth and
// coverage codes and the same colours, and the shading pass must shade
// exactly the pixels the terrain covers. Headless EGL on llvmpipe.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "headless_run.h"
#include "session/scenario_runner.h"
#include "view_tour_scenario.h"

namespace {

constexpr int kW = 256, kH = 192;

struct Frame {
  std::vector<std::uint8_t> rgba;
  std::vector<float> depth;
  long long shaded = -1;  // samples the shading pass passed (-1: no such pass ran)
};

std::vector<Frame> render_tour(const std::string& method, bool deferred) {
  const auto views = render_checks::valley_ridge_skyline();
  auto scenario = render_checks::view_tour_scenario("deferred_shading_test", views, kW, kH, 45.0);
  scenario.render.antialiasing = "off";  // the terrain passes' own pixels
  scenario.render.shading.deferred_shading = deferred;
  ig::session::ScenarioRunner runner(scenario, headless_run(kW, kH, method));
  const auto& channel = runner.channels().front();
  std::vector<Frame> frames;
  for (int f = 0; f < int(views.size()); ++f) {
    runner.render_frame(f);
    Frame frame;
    frame.rgba = channel.target->read_rgba();
    frame.depth = channel.target->read_depth();
    for (const auto& pass : channel.last.passes)
      if (pass.name == "shade" && pass.draw_calls > 0) frame.shaded = pass.samples_passed;
    frames.push_back(std::move(frame));
  }
  return frames;
}

class DeferredShading : public ::testing::TestWithParam<std::string> {};

TEST_P(DeferredShading, GivesThePictureOfShadingInTheTerrainPasses) {
  const auto deferred = render_tour(GetParam(), true), forward = render_tour(GetParam(), false);
  ASSERT_EQ(deferred.size(), forward.size());
  for (size_t f = 0; f < deferred.size(); ++f) {
    const Frame &d = deferred[f], &fw = forward[f];
    ASSERT_EQ(d.depth, fw.depth) << "frame " << f << ": the geometry is the same either way";
    long long terrain_pixels = 0, differing = 0;
    double sum = 0.0;
    int worst = 0;
    for (size_t p = 0; p < d.depth.size(); ++p) {
      terrain_pixels += d.depth[p] > 0.0f;
      ASSERT_EQ(d.rgba[4 * p + 3], fw.rgba[4 * p + 3]) << "frame " << f << " pixel " << p << ": coverage code";
      for (int c = 0; c < 3; ++c) {
        const int diff = std::abs(int(d.rgba[4 * p + c]) - int(fw.rgba[4 * p + c]));
        sum += diff;
        worst = std::max(worst, diff);
        differing += diff > 2;
      }
    }
    const double mean = sum / (3.0 * double(d.depth.size()));
    std::printf("%s frame %zu: %lld terrain pixels, %lld shaded; colour |deferred - forward| mean %.4f, max %d, "
                "%lld channels over 2 levels\n",
                GetParam().c_str(), f, terrain_pixels, d.shaded, mean, worst, differing);
    ASSERT_GT(terrain_pixels, 0);
    EXPECT_EQ(d.shaded, terrain_pixels) << "frame " << f << ": every covered pixel shaded once, no sky pixel";
    EXPECT_EQ(fw.shaded, -1) << "frame " << f << ": no shading pass when the terrain passes shade";
    // The same function of the same values (stored as 32-bit floats): the
    // same bytes.
    EXPECT_EQ(worst, 0) << "frame " << f << ": mean difference " << mean << ", " << differing
                        << " channels over 2 levels";
  }
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, DeferredShading,
                         ::testing::Values("twolevel", "reference", "roam", "geomipmap", "chunked", "quadtree",
                                           "cdlod"),
                         [](const auto& info) { return info.param; });

}  // namespace
