// Image tests of the two-level method (visual/render/twolevel_method.*)
// against the reference renderer, headless (EGL on llvmpipe), small frames.
//
// Each ScenarioRunner owns its own GL context and never makes it current
// again after construction, so only one runner is alive at a time: the
// reference frames are rendered first and kept on the CPU, then the
// two-level runner renders the same poses. Scenarios use a time step of 1 s
// and path keys at whole seconds, so frame k is exactly key k's pose, and
// rendering the same frame again repeats the same camera (the size
// controller settles on a steady view).
//
// Measured figures are printed (std::printf) and recorded as test properties.

#include <gtest/gtest.h>

#include "gl/coverage_codes.h"
#include "render/test/twolevel_checks.h"

namespace {

using namespace twolevel_checks;

// ---------------------------------------------------------------- 1. seam --

struct SeamMetrics {
  long long terrain_px = 0, checked_px = 0, holes = 0, black = 0, nan_depth = 0;
  long long seam_holes = 0;  // holes whose reference point lies within 4 samples of Level1's edge
  // Seam pixels (terrain in both) markedly bluer than the reference's: sky
  // let through part of a pixel (a multisampled frame's hole within a pixel).
  long long seam_px = 0, seam_sky_tinted = 0;
  double horizon_mean = 0.0, horizon_max = 0.0;
  double depth_p95 = 0.0, depth_max = 0.0;
};

// Level1's square in metres, for classifying holes at the seam.
struct Square {
  double x0, y0, x1, y1, margin;
};

SeamMetrics compare(const Frame& ref, const Frame& tl, const Square& sq) {
  auto at_seam = [&](const glm::dvec3& p) {
    const bool in_outer = p.x > sq.x0 - sq.margin && p.x < sq.x1 + sq.margin && p.y > sq.y0 - sq.margin &&
                          p.y < sq.y1 + sq.margin;
    const bool in_inner = p.x > sq.x0 + sq.margin && p.x < sq.x1 - sq.margin && p.y > sq.y0 + sq.margin &&
                          p.y < sq.y1 - sq.margin;
    return in_outer && !in_inner;
  };
  // Horizon, depth and holes from the shared metrics (visual/stats/image_error.h,
  // docs/bench.md). Holes are counted away from the reference's silhouettes
  // (sky within 2 rows and 1 column): pixels there may go either way.
  ig::stats::ImageErrorOptions o;
  o.silhouette_rows = 2;
  o.silhouette_cols = 1;
  o.list_interior_holes = true;
  const ig::stats::ImageError e = ig::stats::image_error(image(tl), image(ref), ref.camera, o);
  SeamMetrics m;
  m.terrain_px = e.reference_terrain_pixels;
  m.checked_px = e.interior_pixels;
  m.holes = e.interior_holes;
  m.nan_depth = e.invalid_depth_pixels;
  for (size_t p : e.interior_hole_pixels) m.seam_holes += at_seam(ref.world(int(p % ref.w), int(p / ref.w)));
  for (int y = 0; y < ref.h; ++y)
    for (int x = 0; x < ref.w; ++x) {
      if (!ref.terrain(x, y) || !tl.terrain(x, y) || !at_seam(ref.world(x, y))) continue;
      const size_t q = (size_t(y) * ref.w + x) * 4;
      const int blue_ref = int(ref.rgba[q + 2]) - ref.rgba[q], blue_tl = int(tl.rgba[q + 2]) - tl.rgba[q];
      ++m.seam_px;
      m.seam_sky_tinted += blue_tl - blue_ref > 24;
    }
  for (size_t p = 0; p < tl.rgba.size(); p += 4)
    if (int(tl.rgba[p]) + tl.rgba[p + 1] + tl.rgba[p + 2] < 12) ++m.black;
  m.horizon_mean = e.horizon_mean_px;
  m.horizon_max = e.horizon_max_px;
  m.depth_p95 = e.depth_rel_p95;
  m.depth_max = e.depth_rel_max;
  return m;
}

// Level0 at the paper's 2048 triangles and at the default 32768; frames
// multisampled (4 samples), post-filtered and plain.
class TwoLevelSeam : public ::testing::TestWithParam<std::tuple<int, std::string>> {};

TEST_P(TwoLevelSeam, HasNoHolesAndErrorsAreBounded) {
  constexpr int kW = 320, kH = 240, kSettle = 15;
  const auto [budget, antialiasing] = GetParam();
  // Poses of the default path (its keys, AGL) plus a low grazing view and a
  // steep look-down, all AGL.
  const Scenario base = default_scenario();
  std::vector<PathKey> keys;
  for (const auto& k : base.path.keys) keys.push_back(k);
  keys.push_back(key(0, 5200, 12500, 12, 95, 0.5));      // grazing: 12 m AGL, level
  keys.push_back(key(0, 12000, 15000, 1500, 200, -75));  // steep look-down
  Scenario s = with_keys(base, keys, AltitudeMode::AboveGround);
  s.render.twolevel.level0_budget = budget;
  s.render.antialiasing = antialiasing;
  const int views = int(keys.size());
  const char* names[] = {"path t=0", "path t=5", "path t=10", "path t=15", "path t=20", "grazing", "look-down"};

  std::vector<Frame> ref(views);
  {
    ScenarioRunner runner(s, options("reference", kW, kH));
    for (int v = 0; v < views; ++v) {
      runner.render_frame(v);
      ref[v] = grab(runner);
    }
  }
  ScenarioRunner runner(s, options("twolevel", kW, kH));
  auto& tl = twolevel(runner);
  long long all_terrain = 0, all_checked = 0, all_holes = 0, all_seam_holes = 0;
  double worst_mean = 0, worst_max = 0, worst_p95 = 0;
  for (int v = 0; v < views; ++v) {
    for (int k = 0; k < kSettle; ++k) runner.render_frame(v);
    const Frame f = grab(runner);
    ASSERT_EQ(f.camera.position, ref[v].camera.position);
    const auto& hf = runner.heightfield();
    const glm::ivec2 o = tl.level1_origin();
    const int n = tl.level1_size();
    const Square sq{o.x * hf.spacing_x_m, o.y * hf.spacing_y_m, (o.x + n - 1) * hf.spacing_x_m,
                    (o.y + n - 1) * hf.spacing_y_m, 4.0 * hf.spacing_x_m};
    const SeamMetrics m = compare(ref[v], f, sq);
    dump(ref[v], "seam" + std::to_string(v) + "_ref");
    dump(f, "seam" + std::to_string(v) + "_twolevel");
    std::printf("[seam] %-10s N=%4d R=%.3f passes=%-22s terrain=%6lld holes=%lld (%.4f%%, at the seam %lld) "
                "black=%lld horizon mean=%.3f max=%.0f px depth p95=%.5f max=%.4f seam px %lld sky-tinted %lld\n",
                names[v], tl.level1_size(), tl.last_ratio(), f.passes.c_str(), m.terrain_px, m.holes,
                m.checked_px ? 100.0 * double(m.holes) / double(m.checked_px) : 0.0, m.seam_holes, m.black,
                m.horizon_mean, m.horizon_max, m.depth_p95, m.depth_max, m.seam_px, m.seam_sky_tinted);
    EXPECT_GT(m.terrain_px, kW * kH / 10) << names[v] << ": the view should show terrain";
    EXPECT_EQ(m.nan_depth, 0) << names[v];
    EXPECT_EQ(m.black, 0) << names[v] << ": black pixels mean holes or NaN shading";
    // No sky through the Level1/Level0 seam. Elsewhere sky where the
    // reference has terrain is Level0's coarseness (a far ridge it cuts
    // lower): part of the image error, bounded per view below.
    // At 32768 triangles one pixel of the path t=5 view is counted: its
    // reference point lies 14 m outside the square's far edge, where Level0
    // (the surface there) cuts a small ridge below the skyline: Level0's
    // error, not a crack between the levels. So at most one per view there.
    EXPECT_LE(m.seam_holes, budget > 2048 ? 1 : 0) << names[v] << ": sky showing through the seam";
    // Nor through part of a seam pixel: multisampled, Level0 discarded only
    // where its whole pixel is inside Level1's square (level0_clipped.frag);
    // a discard by the pixel's centre alone tinted 9-37 seam pixels a view
    // here with sky and left 71 holes in the look-down.
    EXPECT_EQ(m.seam_sky_tinted, 0) << names[v] << ": sky showing through part of seam pixels";
    all_terrain += m.terrain_px;
    all_checked += m.checked_px;
    all_holes += m.holes;
    all_seam_holes += m.seam_holes;
    worst_mean = std::max(worst_mean, m.horizon_mean);
    worst_max = std::max(worst_max, m.horizon_max);
    worst_p95 = std::max(worst_p95, m.depth_p95);
    // Bounds: the measured values (docs/twolevel.md) with margin. The
    // grazing view (12 m above ground, level) used to be the weak spot: with
    // Level1 on E far ahead, Level0 (max error ~100 m) drew the ground beside
    // the eye and a nearby hill 40-90 m too low showed sky (8.7 % holes). The
    // eye guard now makes Level1 cover the ground under a low eye.
    EXPECT_LE(double(m.holes), 0.003 * double(m.checked_px)) << names[v];
    EXPECT_LE(m.horizon_mean, 2.0) << names[v];
    EXPECT_LE(m.horizon_max, 12.0) << names[v];
    EXPECT_LE(m.depth_p95, 0.15) << names[v];
  }
  std::printf("[seam] all views: holes %lld (at the seam %lld) of %lld checked terrain pixels (%lld terrain); "
              "worst horizon mean %.3f px, worst horizon max %.0f px, worst depth p95 %.5f\n",
              all_holes, all_seam_holes, all_checked, all_terrain, worst_mean, worst_max, worst_p95);
  record("holes", double(all_holes));
  record("checked_pixels", double(all_checked));
  record("horizon_mean_px_worst", worst_mean);
  record("horizon_max_px_worst", worst_max);
  record("depth_p95_worst", worst_p95);
}

INSTANTIATE_TEST_SUITE_P(Level0BudgetsAndSamples, TwoLevelSeam,
                         ::testing::Values(std::make_tuple(2048, "msaa"), std::make_tuple(32768, "msaa"),
                                           std::make_tuple(32768, "fxaa"), std::make_tuple(32768, "off")));

// ------------------------------------------------------------- 2. sky only --

// A low eye looking far ahead: E is kilometres away. With the eye guard,
// Level1 holds the ground under the eye (margin included); without it, the
// square sits around E alone and the eye is over Level0.
TEST(TwoLevel, EyeGuardPutsTheGroundUnderALowEyeInLevel1) {
  constexpr int kW = 160, kH = 120;
  for (bool guard : {true, false}) {
    Scenario s = with_keys(default_scenario(), {key(0, 5200, 12500, 40, 95, -1)}, AltitudeMode::AboveGround);
    s.render.twolevel.eye_guard = guard;
    // Squares up to 513 a side: the largest, 1025, which the controller takes
    // for this view, would hold the eye with E 10 km out either way.
    s.render.twolevel.max_level1 = 513;
    ScenarioRunner runner(s, options("twolevel", kW, kH));
    auto& tl = twolevel(runner);
    for (int k = 0; k < 3; ++k) runner.render_frame(0);
    const auto& hf = runner.heightfield();
    const glm::dvec3 eye = runner.channels().front().camera.position;
    const glm::dvec2 e = glm::dvec2(tl.look_at().point);
    const double eye_i = eye.x / hf.spacing_x_m, eye_j = eye.y / hf.spacing_y_m;
    const glm::ivec2 o = tl.level1_origin();
    const int n = tl.level1_size();
    const double inside = std::min({eye_i - o.x, o.x + n - 1 - eye_i, eye_j - o.y, o.y + n - 1 - eye_j});
    std::printf("[guard %s] eye-E %.0f m, N=%d, eye %.1f samples inside Level1 (negative: outside), guarded=%d\n",
                guard ? "on " : "off", glm::length(glm::dvec2(eye) - e), n, inside, int(tl.eye_guarded()));
    ASSERT_GT(glm::length(glm::dvec2(eye) - e), 1000.0) << "the view should put E far from the eye";
    if (guard) {
      EXPECT_TRUE(tl.eye_guarded());
      EXPECT_GE(inside, 31.0) << "the eye should be at least the margin inside Level1";
    } else {
      EXPECT_FALSE(tl.eye_guarded());
      EXPECT_LT(inside, 0.0) << "without the guard Level1 sits around E only";
    }
  }
}

TEST(TwoLevel, SkyOnlyViewRunsNoTerrainPass) {
  // 4000 m above sea level (the default terrain tops out near 2000 m),
  // pitched up 60 degrees: nothing but sky in view.
  const Scenario s = with_keys(default_scenario(), {key(0, 15000, 15000, 4000, 30, 60)}, AltitudeMode::AboveSeaLevel);
  ScenarioRunner runner(s, options("twolevel", 160, 120));
  ASSERT_GT(4000.0, runner.heightfield().max_m);
  for (int k = 0; k < 3; ++k) {
    runner.render_frame(0);
    const Frame f = grab(runner);
    EXPECT_EQ(f.passes, runner.channels().front().target->post_pass() ? "sky+aa" : "sky") << "frame " << k;
    EXPECT_EQ(f.triangles, 0) << "frame " << k;
    long long terrain = 0;
    for (float d : f.depth) terrain += d != 0.0f;
    EXPECT_EQ(terrain, 0);
  }
}

// The coverage ratio R that steers Level1's size is Level1's share of the
// terrain pixels of the finished frame: counted from the frame's coverage
// codes on the same samples (every 4th pixel each way) it must come out
// exactly, also where the view shows sky (pixels the sky pass fills after
// the terrain is drawn must not count as terrain).
TEST(TwoLevel, CoverageRatioIsLevel1sShareOfTheFramesTerrain) {
  constexpr int kW = 203, kH = 150, kStep = 4;  // a width that is no multiple of the step
  const Scenario base = default_scenario();
  for (const char* antialiasing : {"off", "fxaa"}) {
    Scenario s = with_keys(base, {base.path.keys.front()}, AltitudeMode::AboveGround);
    s.render.antialiasing = antialiasing;
    ScenarioRunner runner(s, options("twolevel", kW, kH));
    auto& tl = twolevel(runner);
    runner.render_frame(0);
    const Frame f = grab(runner);
    long long level1 = 0, terrain = 0, sky = 0;
    for (int qy = 0; qy < (kH + kStep - 1) / kStep; ++qy)
      for (int qx = 0; qx < (kW + kStep - 1) / kStep; ++qx) {
        // The count's samples are in GL's rows (bottom first); the frame holds the top row first.
        const int x = std::min(qx * kStep + kStep / 2, kW - 1), y = std::min(qy * kStep + kStep / 2, kH - 1);
        const int a = f.alpha(x, kH - 1 - y);
        level1 += a >= ig::gl::coverage::kAtLeastLevel1 * 255;
        terrain += a >= ig::gl::coverage::kAnyTerrain * 255;
        sky += a < ig::gl::coverage::kAnyTerrain * 255;
      }
    runner.render_frame(0);  // R is read a frame later
    std::printf("[coverage] %s: level1 %lld, terrain %lld, sky %lld samples; R %.4f, counted %.4f\n", antialiasing,
                level1, terrain, sky, tl.last_ratio(), double(level1) / double(terrain));
    ASSERT_GT(sky, 0) << "the view should show sky";
    ASSERT_GT(terrain - level1, 0) << "and Level0";
    EXPECT_DOUBLE_EQ(tl.last_ratio(), double(level1) / double(terrain)) << antialiasing;
  }
}

// ------------------------------------------------------ 3. controller settles --

TEST(TwoLevel, ControllerSettlesOnASteadyView) {
  constexpr int kFrames = 200, kSettleBy = 10;
  const Scenario base = default_scenario();
  for (bool predict : {true, false}) {
    Scenario s = with_keys(base, {base.path.keys.front()}, AltitudeMode::AboveGround);
    s.render.twolevel.predict_size = predict;
    s.render.twolevel.eye_guard = false;  // the controller alone decides the size
    ScenarioRunner runner(s, options("twolevel", 200, 150));
    auto& tl = twolevel(runner);
    const auto& hf = runner.heightfield();
    const auto ladder = ig::lod::level1_ladder(hf.width, hf.height);
    std::vector<int> sizes;
    std::vector<double> ratios;
    for (int k = 0; k < kFrames; ++k) {
      runner.render_frame(0);
      sizes.push_back(tl.level1_size());
      ratios.push_back(tl.last_ratio());
    }
    if (!predict) {
      EXPECT_EQ(sizes.front(), ladder.back()) << "the paper's rule starts at the largest size";
    }
    int changes_after = 0;
    for (int k = kSettleBy + 1; k < kFrames; ++k) changes_after += sizes[k] != sizes[k - 1];
    const double r = ratios.back();
    // R one ladder size smaller, measured on the same view.
    double r_smaller = -1.0;
    if (sizes.back() != ladder.front()) {
      Scenario smaller = s;
      smaller.render.twolevel.max_level1 = sizes.back() / 2 + 1;
      smaller.render.twolevel.predict_size = false;
      ScenarioRunner probe(smaller, options("twolevel", 200, 150));
      for (int k = 0; k < 3; ++k) probe.render_frame(0);
      r_smaller = twolevel(probe).last_ratio();
    }
    std::printf("[controller] %s sizes:", predict ? "predicted" : "stepping ");
    for (int k = 0; k < 16; ++k) std::printf(" %d", sizes[k]);
    std::printf(" ... final %d, R=%.3f (one size smaller: %.3f), changes after frame %d: %d\n", sizes.back(), r,
                r_smaller, kSettleBy, changes_after);
    EXPECT_EQ(changes_after, 0) << "Level1 size still changing (oscillation) after frame " << kSettleBy;
    // Settled at the smallest size that keeps R >= a1: its own R >= a1 (or
    // the top of the ladder), one size smaller < a1 (or the bottom).
    // The paper's rule alone only looks one step ahead with a learnt
    // R(smaller)/R(larger) and may keep a size too large, so only the
    // predicted controller is held to it.
    if (predict) {
      EXPECT_TRUE(r >= 0.5 || sizes.back() == ladder.back()) << "R=" << r;
      EXPECT_TRUE(r_smaller < 0.5 + 0.05) << "one size smaller would do: R=" << r_smaller;
    }
  }
}

}  // namespace
