// The out-the-window picture: anti-aliased edges against a 4 x 4
// supersampled, box-filtered render of the same view, and ground detail
// that gives a low eye texture without aliasing sparkle. Measured on the
// default scenario's generated terrain (always) and on the real Sierra DEM
// (with IG_DEM_DIR). Each figure is printed; the asserts are the goals.
#include <gtest/gtest.h>

#include <cstdio>

#include "picture_checks.h"

namespace {

using picture::ShotSpec;

ig::io::Scenario scenario(const std::string& file) {
  return ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/" + file);
}

// Edges against a supersampled render: multisampled, post-filtered and plain.
struct EdgeFigures {
  double msaa, fxaa, off;
  long long pixels;
};
EdgeFigures edge_figures(const ig::io::Scenario& s, int frame, int w, int h, const char* name) {
  const picture::Shot ss = picture::box_filter(picture::render(s, frame, ShotSpec{4 * w, 4 * h, "off"}), 4);
  const auto msaa = picture::boundary_error(picture::render(s, frame, ShotSpec{w, h, "msaa"}), ss);
  const auto fxaa = picture::boundary_error(picture::render(s, frame, ShotSpec{w, h, "fxaa"}), ss);
  const auto off = picture::boundary_error(picture::render(s, frame, ShotSpec{w, h, "off"}), ss);
  std::printf("[edges %s] boundary pixels %lld, mean |difference| from 16x SS: 4x MSAA %.2f, FXAA %.2f, off %.2f levels\n",
              name, msaa.pixels, msaa.mean, fxaa.mean, off.mean);
  return {msaa.mean, fxaa.mean, off.mean, msaa.pixels};
}

TEST(Picture, AntiAliasedSkylineIsCloseToSupersampled) {
  const EdgeFigures e = edge_figures(scenario("default.json"), 0, 320, 240, "default");
  ASSERT_GT(e.pixels, 200) << "the view should have a skyline";
  EXPECT_LE(e.msaa, 10.0);
  EXPECT_LT(e.msaa, 0.7 * e.off) << "anti-aliasing should cut the edge error well down";
  // The post filter guesses coverage from the picture: about half the error
  // here (12.4 of 26.9 levels measured), short of multisampling.
  EXPECT_LT(e.fxaa, 0.6 * e.off);
}

// Two skylines from Owens Valley: west to the Sierra crest (snow and rock
// far off, in haze) and east to the near Inyo Mountains (bright slopes).
TEST(Picture, SierraSkylinesAreCloseToSupersampled) {
  if (picture::dem_dir().empty()) GTEST_SKIP() << "IG_DEM_DIR not set: real-DEM picture test skipped";
  for (const double heading : {262.0, 80.0}) {
    auto s = scenario("sierra_skyline.json");
    s.path.keys.front().heading_deg = heading;
    const std::string name = "sierra heading " + std::to_string(int(heading));
    const EdgeFigures e = edge_figures(s, 0, 480, 360, name.c_str());
    ASSERT_GT(e.pixels, 300) << name;
    EXPECT_LE(e.msaa, 10.0) << name;
    EXPECT_LT(e.msaa, 0.7 * e.off) << name;
    EXPECT_LT(e.fxaa, 0.8 * e.off) << name;
  }
}

// A low eye over the valley floor: the lower quarter of the picture has
// texture (high-pass luminance), and no more than a supersampled render of
// the same view has (detail, not aliasing sparkle).
TEST(Picture, LowEyeSeesGroundDetailWithoutSparkle) {
  if (picture::dem_dir().empty()) GTEST_SKIP() << "IG_DEM_DIR not set: real-DEM picture test skipped";
  const auto s = scenario("sierra_low_30m.json");
  const int w = 480, h = 360;
  const double on = picture::highpass_std_lower_quarter(picture::render(s, 0, ShotSpec{w, h, "msaa"}));
  const double fxaa = picture::highpass_std_lower_quarter(picture::render(s, 0, ShotSpec{w, h, "fxaa"}));
  const double off = picture::highpass_std_lower_quarter(picture::render(s, 0, ShotSpec{w, h, "msaa", false}));
  const double ss =
      picture::highpass_std_lower_quarter(picture::box_filter(picture::render(s, 0, ShotSpec{4 * w, 4 * h, "off"}), 4));
  std::printf("[detail sierra 30 m] high-pass std, lower quarter: detail %.2f (FXAA %.2f), no detail %.2f, "
              "16x SS %.2f levels\n", on, fxaa, off, ss);
  EXPECT_GE(on, 2.0);
  EXPECT_GE(fxaa, 2.0) << "the post filter must not smooth the detail away";
  EXPECT_LT(off, 1.0) << "without detail the valley floor is smooth";
  EXPECT_LE(on, 1.5 * ss);
  EXPECT_LE(fxaa, 1.5 * ss);
}

// The same on generated terrain, so the goal is checked without the DEM.
TEST(Picture, GeneratedTerrainSeesGroundDetailWithoutSparkle) {
  auto s = scenario("default.json");
  const int w = 320, h = 240;
  const double on = picture::highpass_std_lower_quarter(picture::render(s, 0, ShotSpec{w, h, "msaa"}));
  const double off = picture::highpass_std_lower_quarter(picture::render(s, 0, ShotSpec{w, h, "msaa", false}));
  const double ss =
      picture::highpass_std_lower_quarter(picture::box_filter(picture::render(s, 0, ShotSpec{4 * w, 4 * h, "off"}), 4));
  std::printf("[detail default] high-pass std, lower quarter: detail %.2f, no detail %.2f, 16x SS %.2f levels\n", on,
              off, ss);
  EXPECT_GT(on, 2.0 * off);
  EXPECT_LE(on, 1.5 * ss);
}

// The detail is fixed to the terrain: its tile coordinate starts from a
// whole sample near the eye (render/terrain_scene.cpp). Moving the eye by
// 1 mm across a sample boundary changes that anchor but must not move the
// detail on the ground: the two pictures are the same to a fraction of a
// level, where a wrong phase would shift the texture by up to a tile.
TEST(Picture, DetailDoesNotMoveWhenTheEyeCrossesASample) {
  auto s = scenario("default.json");
  const double x = 260.0 * 30.0;  // a sample boundary of the generated 30 m grid
  ig::io::PathKey a;
  a.position = {x - 0.0005, 5000.0, 40.0};
  a.heading_deg = 10.0;
  a.pitch_deg = -20.0;
  ig::io::PathKey b = a;
  b.t_s = 1.0;
  b.position[0] = x + 0.0005;
  s.path.frame = ig::io::PositionFrame::Local;
  s.path.altitude = ig::io::AltitudeMode::AboveGround;
  s.path.keys = {a, b};
  s.time_step_s = 1.0;
  s.duration_s = 1.0;
  s.capture_times_s.clear();
  const picture::Shot before = picture::render(s, 0, ShotSpec{320, 240, "msaa"});
  const picture::Shot after = picture::render(s, 1, ShotSpec{320, 240, "msaa"});
  const double d = picture::mean_abs_difference(before, after);
  std::printf("[detail anchor] 1 mm across a sample boundary: mean |difference| %.4f levels\n", d);
  EXPECT_LT(d, 0.05);
}

}  // namespace
