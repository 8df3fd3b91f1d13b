// Multi-channel views: each channel is the body pose turned by its view
// offset; with horizontal FOV = heading step (scenarios/three_channels.json)
// neighbouring views meet exactly at their shared edge.
#include <gtest/gtest.h>

#include <cmath>

#include "session/scenario_runner.h"
#include "io/scenario.h"
#include "render/twolevel_method.h"

namespace {

ig::session::RunOptions small(const std::string& method) {
  ig::session::RunOptions o;
  o.headless = true;
  o.method = method;
  o.shader_dir = std::string(IG_BIN_DIR) + "/shaders";
  return o;
}

TEST(Channels, NeighbouringViewsShareTheirEdgeRays) {
  ig::session::ScenarioRunner runner(ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/three_channels.json"),
                                 small("reference"));
  runner.render_frame(0);
  auto& ch = runner.channels();
  ASSERT_EQ(ch.size(), 3u);
  const int w = ch[0].target->width(), h = ch[0].target->height();
  for (int y : {0, h / 2, h - 1}) {
    for (int pair = 0; pair < 2; ++pair) {
      // Right boundary of channel k == left boundary of channel k + 1 (pixel_ray
      // takes pixel-centre coordinates: px + 0.5 = boundary).
      const glm::dvec3 a = ch[pair].camera.pixel_ray(w - 0.5, y, w, h);
      const glm::dvec3 b = ch[pair + 1].camera.pixel_ray(-0.5, y, w, h);
      EXPECT_NEAR(glm::length(a - b), 0.0, 1e-4) << "pair " << pair << " row " << y;
    }
  }
  // And the images agree across the seam: last column of one, first of the next.
  for (int pair = 0; pair < 2; ++pair) {
    const auto left = ch[pair].target->read_rgba(), right = ch[pair + 1].target->read_rgba();
    double diff = 0;
    for (int y = 0; y < h; ++y)
      for (int c = 0; c < 3; ++c)
        diff += std::abs(int(left[(size_t(y) * w + w - 1) * 4 + c]) - int(right[(size_t(y) * w) * 4 + c]));
    const double mean = diff / (3.0 * h);
    std::printf("channel seam %d: mean |colour difference| across the edge %.2f / 255\n", pair, mean);
    EXPECT_LT(mean, 12.0);
  }
}

TEST(Channels, EachChannelHasItsOwnLodState) {
  ig::session::ScenarioRunner runner(ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/three_channels.json"),
                                 small("twolevel"));
  runner.render_frame(0);
  auto& ch = runner.channels();
  EXPECT_NE(ch[0].method.get(), ch[1].method.get());
  // Each channel centres its Level1 on where its own view looks.
  const auto* left = dynamic_cast<ig::render::TwoLevelMethod*>(ch[0].method.get());
  const auto* centre = dynamic_cast<ig::render::TwoLevelMethod*>(ch[1].method.get());
  ASSERT_TRUE(left && centre);
  EXPECT_GT(glm::length(left->look_at().point - centre->look_at().point), 100.0);
  // ... but the view-independent height pyramid is built once and shared.
  EXPECT_EQ(&left->pyramid(), &centre->pyramid());
  EXPECT_EQ(&left->pyramid(), &runner.scene().height_pyramid());
}

}  // namespace
