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
// Long because every two-level feature (band, eye guard, seams, envelope,
// size control, skip-pass) is checked here against the same reference frames.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>

#include "capture/png_writer.h"
#include "session/scenario_runner.h"
#include "io/pose.h"
#include "io/scenario.h"
#include "lod/level1_size_controller.h"
#include "render/twolevel_method.h"
#include "stats/image_error.h"

namespace {

using namespace ig::io;
using namespace ig::session;

ig::io::Scenario default_scenario() {
  return ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json");
}

RunOptions options(const std::string& method, int w, int h) {
  RunOptions o;
  o.width = w;
  o.height = h;
  o.method = method;
  o.headless = true;
  o.shader_dir = std::string(IG_BIN_DIR) + "/shaders";
  return o;
}

PathKey key(double t, double x, double y, double z, double heading, double pitch, double roll = 0.0) {
  PathKey k;
  k.t_s = t;
  k.position = {x, y, z};
  k.heading_deg = heading;
  k.pitch_deg = pitch;
  k.roll_deg = roll;
  return k;
}

// The scenario with its path replaced: key k at t = k seconds, 1 s steps,
// so render_frame(k) shows key k exactly (and frames past the end the last key).
Scenario with_keys(Scenario s, std::vector<PathKey> keys, AltitudeMode altitude) {
  for (size_t k = 0; k < keys.size(); ++k) keys[k].t_s = double(k);
  s.path.frame = ig::io::PositionFrame::Local;
  s.path.altitude = altitude;
  s.path.keys = std::move(keys);
  s.time_step_s = 1.0;
  s.duration_s = double(s.path.keys.size() - 1);
  s.capture_times_s.clear();
  return s;
}

ig::render::TwoLevelMethod& twolevel(ScenarioRunner& r) {
  auto* m = dynamic_cast<ig::render::TwoLevelMethod*>(&r.method());
  if (!m) throw std::runtime_error("runner's method is not twolevel");
  return *m;
}

struct Frame {
  int w = 0, h = 0;
  std::vector<float> depth;
  std::vector<std::uint8_t> rgba;
  ig::render::Camera camera;
  std::string passes;
  long long triangles = 0;
  bool terrain(int x, int y) const { return depth[size_t(y) * w + x] > 0.0f; }
  float d(int x, int y) const { return depth[size_t(y) * w + x]; }
  std::uint8_t alpha(int x, int y) const { return rgba[(size_t(y) * w + x) * 4 + 3]; }
  double view_distance(int x, int y) const { return camera.depth_to_view_distance(d(x, y)); }
  // World position of the surface seen at pixel (x, y) (terrain pixels only).
  glm::dvec3 world(int x, int y) const {
    const glm::dvec3 ray = camera.pixel_ray(x, y, w, h);
    const double t = view_distance(x, y) / glm::dot(ray, camera.forward());
    return camera.position + ray * t;
  }
};

ig::stats::FrameImage image(const Frame& f) { return {f.w, f.h, f.rgba, f.depth}; }

Frame grab(ScenarioRunner& r) {
  auto& ch = r.channels().front();
  Frame f;
  f.w = ch.target->width();
  f.h = ch.target->height();
  f.depth = ch.target->read_depth();
  f.rgba = ch.target->read_rgba();
  f.camera = ch.camera;
  f.passes = ch.last.method.passes;
  f.triangles = ch.last.method.triangles;
  return f;
}

// With IG_TWOLEVEL_DUMP=<dir> set, frames are written there as PNG (alpha
// forced opaque) for a look.
void dump(const Frame& f, const std::string& name) {
  const char* dir = std::getenv("IG_TWOLEVEL_DUMP");
  if (!dir || !*dir) return;
  auto rgba = f.rgba;
  for (size_t p = 3; p < rgba.size(); p += 4) rgba[p] = 255;
  ig::capture::write_png_rgba(std::string(dir) + "/" + name + ".png", rgba, f.w, f.h);
}

void record(const std::string& name, double value) {
  ::testing::Test::RecordProperty(name, std::to_string(value));
}

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

// ------------------------------------------------------------ 4. no swimming --

TEST(TwoLevel, Level1VerticesStayOnDemSamplesWhenTheEyeMoves) {
  constexpr int kW = 320, kH = 240, kSettle = 15;
  const Scenario base = default_scenario();
  // The default path's first pose in absolute metres (MSL).
  glm::dvec3 eye;
  ig::io::Hpr hpr;
  double spacing = 0.0;
  {
    ScenarioRunner probe(with_keys(base, {base.path.keys.front()}, AltitudeMode::AboveGround),
                         options("twolevel", 64, 48));
    probe.render_frame(0);
    const auto pose = probe.pose_at(0.0);
    eye = pose.position;
    hpr = ig::io::hpr_from_attitude(pose.attitude);
    spacing = probe.heightfield().spacing_x_m;
    // Put E about 0.15 samples below a sample centre so that the 0.3-sample
    // move keeps it closest to the same sample (same snapped origin).
    const glm::dvec3 e = twolevel(probe).look_at().point;
    auto frac = [](double v) { return v - std::round(v); };
    eye.x -= (frac(e.x / spacing) + 0.15) * spacing;
    eye.y -= (frac(e.y / spacing) + 0.15) * spacing;
  }
  const double shift = 0.3 * spacing;
  Scenario s = with_keys(
      base,
      {key(0, eye.x, eye.y, eye.z, hpr.heading_deg, hpr.pitch_deg, hpr.roll_deg),
       key(0, eye.x + shift, eye.y + shift, eye.z, hpr.heading_deg, hpr.pitch_deg, hpr.roll_deg)},
      AltitudeMode::AboveSeaLevel);
  // Single-sampled: the surface point of a pixel is found from its depth,
  // which must be the depth at the pixel's centre (a multisampled frame
  // resolves to one of its samples).
  s.render.antialiasing = "off";
  ScenarioRunner runner(s, options("twolevel", kW, kH));
  auto& tl = twolevel(runner);
  const auto& hf = runner.heightfield();
  struct Render {
    Frame f;
    int n = 0;
    glm::ivec2 origin{0};
    glm::dvec3 e{0.0};
  };
  Render rs[2];
  for (int v = 0; v < 2; ++v) {
    for (int k = 0; k < kSettle; ++k) runner.render_frame(v);
    rs[v] = {grab(runner), tl.level1_size(), tl.level1_origin(), tl.look_at().point};
  }
  std::printf("[swim] A: N=%d origin=(%d,%d) E=(%.2f,%.2f)  B: N=%d origin=(%d,%d) E=(%.2f,%.2f)\n", rs[0].n,
              rs[0].origin.x, rs[0].origin.y, rs[0].e.x, rs[0].e.y, rs[1].n, rs[1].origin.x, rs[1].origin.y,
              rs[1].e.x, rs[1].e.y);
  ASSERT_EQ(rs[0].n, rs[1].n) << "the controller should settle to the same size for a 0.3-sample move";
  EXPECT_EQ(rs[0].origin, rs[1].origin) << "E snapped to whole samples: a 0.3-sample move keeps the origin";
  EXPECT_NE(rs[0].f.camera.position, rs[1].f.camera.position);

  for (int v = 0; v < 2; ++v) {
    const Render& r = rs[v];
    const double x0 = (r.origin.x + 1) * hf.spacing_x_m, x1 = (r.origin.x + r.n - 2) * hf.spacing_x_m;
    const double y0 = (r.origin.y + 1) * hf.spacing_y_m, y1 = (r.origin.y + r.n - 2) * hf.spacing_y_m;
    long long level1 = 0, checked = 0, off = 0;
    double worst = 0.0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        if (r.f.alpha(x, y) != 255 || !r.f.terrain(x, y)) continue;
        ++level1;
        const glm::dvec3 p = r.f.world(x, y);
        // Skip the walls along Level1's edge (one sample wide).
        if (p.x < x0 || p.x > x1 || p.y < y0 || p.y > y1) continue;
        ++checked;
        const double dist = glm::length(p - r.f.camera.position);
        const double err = std::abs(p.z - hf.sample_surface(p.x, p.y));
        const double tol = 0.05 + 1e-4 * dist;
        worst = std::max(worst, err / tol);
        off += err > tol;
      }
    std::printf("[swim] render %c: Level1 pixels %lld, checked %lld, off the DEM surface %lld, worst err/tol %.3f\n",
                'A' + v, level1, checked, off, worst);
    EXPECT_GT(checked, kW * kH / 20) << "render " << v << ": too few Level1 pixels to check";
    EXPECT_EQ(off, 0) << "render " << v << ": Level1 pixels off the DEM surface (swimming)";
  }
}

// --------------------------------------------------------- 5. ridge occlusion --

// Flat ground at 0 m with a 300 m wall across the whole width at
// j = [ridge_j0, ridge_j0 + 4], written as an ESRI ASCII grid (10 m cells).
struct RidgeDem {
  int w = 600, h = 1000;
  double spacing = 10.0;
  int ridge_j0 = 100, ridge_j1 = 104;
  double ridge_m = 300.0;
  std::string path;
};

RidgeDem write_ridge_dem() {
  RidgeDem d;
  const auto dir = std::filesystem::temp_directory_path() / "ig_twolevel_test";
  std::filesystem::create_directories(dir);
  d.path = (dir / "ridge.asc").string();
  std::ofstream o(d.path);
  o << "ncols " << d.w << "\nnrows " << d.h << "\nxllcorner 0\nyllcorner 0\ncellsize " << d.spacing
    << "\nNODATA_value -9999\n";
  for (int row = 0; row < d.h; ++row) {  // north first
    const int j = d.h - 1 - row;
    const bool ridge = j >= d.ridge_j0 && j <= d.ridge_j1;
    for (int i = 0; i < d.w; ++i) o << (ridge ? "300" : "0") << (i + 1 < d.w ? ' ' : '\n');
  }
  return d;
}

TEST(TwoLevel, Level0RidgeOccludesLevel1) {
  constexpr int kW = 320, kH = 240, kSettle = 15;
  const RidgeDem dem = write_ridge_dem();
  Scenario s = default_scenario();
  s.terrain.generator.reset();
  s.terrain.file = dem.path;
  s.terrain.spacing_m = dem.spacing;
  // Eye 300 m south of the wall at 400 m, looking north 7 degrees down: the
  // centre ray clears the wall top (363 m there) and meets the ground ~3.2 km
  // out, so E and Level1 lie beyond the wall, whose top is 11 degrees below
  // the centre: the lower quarter of the frame shows the wall in front of Level1.
  const double eye_y = (dem.ridge_j0 * dem.spacing) - 300.0;
  s = with_keys(s, {key(0, 3000, eye_y, 400, 0, -7)}, AltitudeMode::AboveSeaLevel);
  // The eye guard would grow Level1 over the eye and the wall (400 m is low
  // for this flat DEM's Level0): off, so the wall stays Level0 in front of Level1.
  s.render.twolevel.eye_guard = false;

  Frame ref;
  {
    ScenarioRunner runner(s, options("reference", kW, kH));
    runner.render_frame(0);
    ref = grab(runner);
  }
  ScenarioRunner runner(s, options("twolevel", kW, kH));
  auto& tl = twolevel(runner);
  for (int k = 0; k < kSettle; ++k) runner.render_frame(0);
  const Frame f = grab(runner);
  const int n = tl.level1_size();
  const glm::ivec2 o = tl.level1_origin();
  std::printf("[ridge] N=%d origin=(%d,%d) E=(%.0f,%.0f) hit=%d R=%.3f passes=%s\n", n, o.x, o.y,
              tl.look_at().point.x, tl.look_at().point.y, int(tl.look_at().hit), tl.last_ratio(), f.passes.c_str());
  ASSERT_TRUE(tl.look_at().hit);
  ASSERT_NE(f.passes.find("level1"), std::string::npos);
  // The Level1 square lies wholly north of the wall.
  ASSERT_GT(o.y, dem.ridge_j1) << "Level1 contains the ridge: the test would not exercise occlusion";

  // Pixels where the reference sees the wall (world y on the wall, height above 1 m).
  long long wall_px = 0, wrong = 0, level1_marked = 0;
  double worst = 0.0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      if (!ref.terrain(x, y)) continue;
      const glm::dvec3 p = ref.world(x, y);
      const bool on_wall = p.y > (dem.ridge_j0 - 1) * dem.spacing && p.y < (dem.ridge_j1 + 1) * dem.spacing && p.z > 1.0;
      if (!on_wall) continue;
      // Away from the wall's top edge (Level0 may round it), 2 rows.
      bool edge = false;
      for (int dy = -2; dy <= 2 && !edge; ++dy) {
        const int yy = std::clamp(y + dy, 0, kH - 1);
        edge = !ref.terrain(x, yy) || ref.world(x, yy).y > (dem.ridge_j1 + 1) * dem.spacing;
      }
      if (edge) continue;
      ++wall_px;
      if (!f.terrain(x, y)) { ++wrong; continue; }
      const double dr = ref.view_distance(x, y), dt = f.view_distance(x, y);
      const double rel = std::abs(dt - dr) / dr;
      worst = std::max(worst, rel);
      wrong += rel > 0.03;
      level1_marked += f.alpha(x, y) == 255;
    }
  // Level1 really lies behind the wall on screen: ground points of Level1's
  // square near its southern edge project onto pixels where the reference
  // sees the (much nearer) wall.
  const auto& hf = runner.heightfield();
  const glm::mat4 vp = f.camera.view_projection();
  int behind = 0;
  for (int j = o.y; j < o.y + 48; j += 8)
    for (int i = o.x; i < o.x + n; i += 8) {
      const glm::dvec3 q(i * hf.spacing_x_m, j * hf.spacing_y_m, 0.0);
      const glm::vec4 c = vp * glm::vec4(glm::vec3(q - f.camera.position), 1.0f);
      if (c.w <= 0) continue;
      const int px = int((c.x / c.w * 0.5 + 0.5) * kW), py = int((0.5 - c.y / c.w * 0.5) * kH);
      if (px < 0 || py < 0 || px >= kW || py >= kH || !ref.terrain(px, py)) continue;
      behind += ref.view_distance(px, py) < 0.5 * glm::dot(q - f.camera.position, f.camera.forward());
    }
  std::printf("[ridge] wall pixels %lld, wrong %lld (level1-marked %lld), worst |dD|/D %.4f, Level1 near-edge "
              "points hidden by the wall %d\n",
              wall_px, wrong, level1_marked, worst, behind);
  EXPECT_GT(wall_px, kW * kH / 10) << "the wall should fill a good part of the frame";
  EXPECT_GT(behind, 3) << "part of Level1 should lie behind the wall on screen";
  EXPECT_EQ(wrong, 0) << "Level1 painted over the Level0 wall (or a hole)";
  EXPECT_EQ(level1_marked, 0);
  record("ridge_wall_pixels", double(wall_px));
  record("ridge_worst_rel_depth", worst);
}

// ------------------------------------------------------- 6. E falls back --

TEST(TwoLevel, LookAtPointFallsBackContinuously) {
  const Scenario base = default_scenario();
  // Sky view: high above everything, pitched up.
  {
    const Scenario s = with_keys(base, {key(0, 15000, 15000, 4000, 30, 60)}, AltitudeMode::AboveSeaLevel);
    ScenarioRunner runner(s, options("twolevel", 64, 48));
    runner.render_frame(0);
    const auto& e = twolevel(runner).look_at();
    const auto& hf = runner.heightfield();
    EXPECT_FALSE(e.hit);
    EXPECT_TRUE(std::isfinite(e.point.x) && std::isfinite(e.point.y) && std::isfinite(e.point.z));
    EXPECT_GE(e.point.x, 0.0);
    EXPECT_LE(e.point.x, hf.extent_x_m());
    EXPECT_GE(e.point.y, 0.0);
    EXPECT_LE(e.point.y, hf.extent_y_m());
  }
  // Pitch sweep -5 .. +5 degrees from the default path's first position.
  const PathKey p0 = base.path.keys.front();
  std::vector<PathKey> keys;
  for (int p = -5; p <= 5; ++p) keys.push_back(key(0, p0.position[0], p0.position[1], p0.position[2], p0.heading_deg, p));
  const Scenario s = with_keys(base, keys, AltitudeMode::AboveGround);
  ScenarioRunner runner(s, options("twolevel", 64, 48));
  auto& tl = twolevel(runner);
  const auto& hf = runner.heightfield();
  glm::dvec3 prev{0.0};
  bool prev_hit = false;
  double max_jump = 0.0, max_jump_same = 0.0, switch_jump = 0.0;
  for (int k = 0; k < int(keys.size()); ++k) {
    runner.render_frame(k);
    const auto e = tl.look_at();
    ASSERT_TRUE(std::isfinite(e.point.x) && std::isfinite(e.point.y) && std::isfinite(e.point.z)) << k;
    EXPECT_GE(e.point.x, 0.0);
    EXPECT_LE(e.point.x, hf.extent_x_m());
    EXPECT_GE(e.point.y, 0.0);
    EXPECT_LE(e.point.y, hf.extent_y_m());
    double jump = 0.0;
    if (k > 0) {
      jump = glm::length(glm::dvec2(e.point - prev));
      max_jump = std::max(max_jump, jump);
      if (e.hit == prev_hit) max_jump_same = std::max(max_jump_same, jump);
      else switch_jump = std::max(switch_jump, jump);
    }
    const double dist = glm::length(glm::dvec2(e.point - runner.channels().front().camera.position));
    std::printf("[lookat] pitch %+d: hit=%d E=(%.0f, %.0f, %.0f) horiz dist %.0f m, jump %.0f m\n", k - 5,
                int(e.hit), e.point.x, e.point.y, e.point.z, dist, jump);
    prev = e.point;
    prev_hit = e.hit;
  }
  std::printf("[lookat] largest jump per degree %.0f m (same mode %.0f m, at a hit<->fallback switch %.0f m)\n",
              max_jump, max_jump_same, switch_jump);
  record("lookat_max_jump_m", max_jump);
  record("lookat_switch_jump_m", switch_jump);
  // E stays inside the DEM (asserted per frame above). At the hit <-> fallback
  // switch it moves no more than a 1-degree step moves it while the ray hits
  // (measured 211 m against 1.3 km; it was 11.3 km before the continuous
  // fallback, docs/twolevel.md).
  EXPECT_LE(switch_jump, max_jump_same);
}

}  // namespace
