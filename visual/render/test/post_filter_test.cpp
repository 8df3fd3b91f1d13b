// The anti-aliasing post filter (gl/post_filter_pass.h): run only on the
// pixels its first draw marks, it must give the picture of the filter run
// on every pixel, byte for byte, and its second draw must pass only the
// marked pixels: a share of the frame, not all of it. Headless EGL on
// llvmpipe, views of a generated terrain with skylines and ridges.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "headless_run.h"
#include "session/scenario_runner.h"
#include "view_tour_scenario.h"

namespace {

constexpr int kW = 320, kH = 240;

struct Frame {
  std::vector<std::uint8_t> rgba;
  unsigned long long aa_draws = 0, aa_passed = 0;
};

std::vector<Frame> render_tour(const std::string& method, bool masked) {
  const auto views = render_checks::valley_ridge_skyline();
  auto scenario = render_checks::view_tour_scenario("post_filter_test", views, kW, kH, 45.0);
  scenario.render.antialiasing = "fxaa";
  ig::session::ScenarioRunner runner(scenario, headless_run(kW, kH, method));
  const auto& channel = runner.channels().front();
  channel.renderer->set_post_filter_mask(masked);
  std::vector<Frame> frames;
  for (int f = 0; f < int(views.size()); ++f) {
    runner.render_frame(f);
    Frame frame;
    frame.rgba = channel.target->read_rgba();
    for (const auto& pass : channel.last.passes)
      if (pass.name == "aa") {
        frame.aa_draws = pass.draw_calls;
        frame.aa_passed = pass.samples_passed;
      }
    frames.push_back(std::move(frame));
  }
  return frames;
}

class PostFilter : public ::testing::TestWithParam<std::string> {};

TEST_P(PostFilter, MarkedPixelsAloneGiveThePictureOfFilteringEveryPixel) {
  const auto masked = render_tour(GetParam(), true), everywhere = render_tour(GetParam(), false);
  ASSERT_EQ(masked.size(), everywhere.size());
  const unsigned long long pixels = kW * kH;
  for (size_t f = 0; f < masked.size(); ++f) {
    const Frame &m = masked[f], &e = everywhere[f];
    long long differing = 0;
    for (size_t i = 0; i < m.rgba.size(); ++i) differing += m.rgba[i] != e.rgba[i];
    // The mark draw passes every pixel, the filter's draw the marked ones.
    const unsigned long long marked = m.aa_passed - pixels;
    std::printf("%s frame %zu: %llu of %llu pixels filtered, %lld bytes differ\n", GetParam().c_str(), f, marked,
                pixels, differing);
    EXPECT_EQ(differing, 0) << "frame " << f;
    EXPECT_EQ(m.aa_draws, 2u);
    EXPECT_EQ(e.aa_draws, 1u);
    EXPECT_EQ(e.aa_passed, pixels) << "frame " << f << ": one draw over every pixel";
    ASSERT_GE(m.aa_passed, pixels) << "frame " << f;
    EXPECT_GT(marked, 0u) << "frame " << f << ": a view with a skyline or ridges has edges to filter";
    EXPECT_LT(marked, pixels / 2) << "frame " << f << ": most pixels lie on no edge";
  }
}

INSTANTIATE_TEST_SUITE_P(TwoMethods, PostFilter, ::testing::Values("twolevel", "cdlod"),
                         [](const auto& info) { return info.param; });

}  // namespace
