// The two-level selection as a value, without a GL context: the far rule
// (Level1 at its smallest when E is far out), the eye guard (Level1 holds a
// low eye), the size controller's steps on the measured ratio, and the
// paging hold (Level1 keeps its square while the new one's heights are not
// resident).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>

#include "io/pose.h"
#include "lod/level0_budget.h"
#include "lod/level0_clusters.h"
#include "lod/twolevel_selection.h"
#include "terrain/height_pyramid.h"
#include "terrain/synthetic_terrain.h"

namespace {

using ig::lod::TwoLevelSelection;
using ig::lod::TwoLevelSelector;
using ig::lod::TwoLevelView;

constexpr int kW = 320, kH = 240;
constexpr double kFovY = 60.0;

// 513 x 513 samples at 30 m: the GL tests' landscape.
struct World {
  ig::terrain::Heightfield hf;
  ig::terrain::HeightPyramid pyramid;
  World() : hf(ig::terrain::generate_synthetic_terrain(options_of_size(513))), pyramid(hf) {}
  static ig::options::SyntheticTerrainOptions options_of_size(int size) {
    ig::options::SyntheticTerrainOptions o;
    o.size = size;
    return o;
  }

  TwoLevelSelector selector(ig::options::TwoLevelOptions options) const {
    auto level0 = ig::lod::z_ordered(ig::lod::build_level0_mesh(hf, {options.level0_budget}));
    return TwoLevelSelector(hf, pyramid, std::move(level0), options);
  }
};

// A pinhole view `agl` metres above the ground at sample (i, j); every box
// counts as in view (the conservative answer the contract allows).
TwoLevelView view_at(const ig::terrain::Heightfield& hf, double i, double j, double agl, double heading,
                     double pitch) {
  const double x = i * hf.spacing_x_m, y = j * hf.spacing_y_m;
  const glm::dquat q = ig::io::attitude_from_hpr({heading, pitch, 0.0});
  TwoLevelView v;
  v.position = {x, y, hf.sample_surface(x, y) + agl};
  v.forward = q * glm::dvec3(0, 1, 0);
  v.up = q * glm::dvec3(0, 0, 1);
  v.viewport = {kW, kH};
  v.pixels_per_radian = ig::lod::pixels_per_radian(kH, kFovY);
  const glm::dvec3 right = q * glm::dvec3(1, 0, 0), forward = v.forward, up = v.up;
  v.box_in_view = [](const glm::dvec3&, const glm::dvec3&) { return true; };
  v.pixel_ray = [=](double px, double py) {
    const double t = std::tan(glm::radians(kFovY) * 0.5);
    const double nx = ((px + 0.5) / kW * 2.0 - 1.0) * t * (double(kW) / kH);
    const double ny = (1.0 - (py + 0.5) / kH * 2.0) * t;
    return glm::normalize(forward + right * nx + up * ny);
  };
  v.screen_rect = [](const glm::dvec3&, const glm::dvec3&) { return glm::ivec4(0, 0, kW, kH); };
  return v;
}

bool holds(const TwoLevelSelection& s, glm::ivec2 sample) {
  return sample.x >= s.origin.x && sample.y >= s.origin.y && sample.x <= s.origin.x + s.n - 1 &&
         sample.y <= s.origin.y + s.n - 1;
}

TEST(TwoLevelSelection, AFarLookAtPointGetsTheSmallestSquareUnderTheEye) {
  const World world;
  ig::options::TwoLevelOptions options;
  options.max_level1 = 65;       // ladder 33, 65: the largest square reaches 1.4 km from E
  options.level0_budget = 8192;  // a coarse Level0: metres of error
  auto selector = world.selector(options);
  const double s = world.hf.spacing_x_m;
  // High over one corner, looking across the map at a low angle: E ~20 km out.
  const auto far_view = view_at(world.hf, 10, 10, 3000.0, 45.0, -8.0);
  const auto& far = selector.select(far_view, -1.0);
  const double distance = glm::length(far.look_at.point - far_view.position);
  const double reach = 0.5 * std::sqrt(2.0) * 64 * s;
  const double error_px = selector.level0().max_error_m * far_view.pixels_per_radian / (distance - reach);
  std::printf("far view: E %.0f m away, Level0's largest error %.2f m = %.3f px at the square's nearest reach\n",
              distance, selector.level0().max_error_m, error_px);
  ASSERT_LT(error_px, TwoLevelSelector::kFarLevel0ErrorPx) << "the view is not far enough for the rule";
  EXPECT_TRUE(far.far);
  EXPECT_EQ(far.n, 33);
  EXPECT_TRUE(holds(far, {10, 10})) << "the square holds the eye's sample, not E's";

  // Looking down near the eye: the rule does not apply, the controller sizes Level1.
  const auto near_view = view_at(world.hf, 250, 250, 150.0, 45.0, -30.0);
  for (int k = 0; k < 4; ++k) selector.select(near_view, -1.0);
  EXPECT_FALSE(selector.last().far);
}

TEST(TwoLevelSelection, ALowEyeLooksAwayYetLevel1HoldsIt) {
  const World world;
  ig::options::TwoLevelOptions options;
  options.level0_budget = 2048;
  options.max_level1 = 129;  // ladder 33, 65, 129: no square around E reaches the eye
  auto selector = world.selector(options);
  // 40 m over the ground, looking nearly level: E is kilometres ahead, but
  // Level0's error right under the eye would show, so the guard grows or
  // moves Level1 to hold the eye too.
  const auto low = view_at(world.hf, 100, 100, 40.0, 45.0, -1.0);
  const auto& sel = selector.select(low, -1.0);
  std::printf("low eye: E %.0f m away, N=%d, origin (%d, %d), Level0 error %.1f m\n",
              glm::length(sel.look_at.point - low.position), sel.n, sel.origin.x, sel.origin.y,
              selector.level0().max_error_m);
  ASSERT_GT(glm::length(sel.look_at.point - low.position), 1000.0) << "the view should put E far from the eye";
  EXPECT_TRUE(sel.eye_guarded);
  EXPECT_TRUE(holds(sel, {100, 100}));
  EXPECT_FALSE(sel.far);

  ig::options::TwoLevelOptions unguarded = options;
  unguarded.eye_guard = false;
  auto plain = world.selector(unguarded);
  const auto& unheld = plain.select(low, -1.0);
  EXPECT_FALSE(unheld.eye_guarded);
  EXPECT_FALSE(holds(unheld, {100, 100})) << "without the guard Level1 sits around E only";
}

TEST(TwoLevelSelection, TheSizeFollowsTheMeasuredRatio) {
  const World world;
  ig::options::TwoLevelOptions options;
  options.level0_budget = 2048;
  options.predict_size = false;  // the paper's one ladder step per frame on R alone
  options.eye_guard = false;
  auto selector = world.selector(options);
  const auto view = view_at(world.hf, 150, 150, 600.0, 45.0, -30.0);
  auto step_down = [](int n) { return (n - 1) / 2 + 1; };
  const int top = selector.select(view, -1.0).n;  // no measurement yet: the controller's start
  // R > 0.98 (Level1 covers all the terrain) always steps down.
  const int lower = selector.select(view, 0.99).n;
  EXPECT_EQ(lower, step_down(top));
  EXPECT_EQ(selector.select(view, 0.99).n, step_down(lower));
  EXPECT_EQ(selector.select(view, 0.65).n, step_down(lower));  // a1 <= R <= a2: kept
  EXPECT_EQ(selector.select(view, 0.1).n, lower);  // R < a1: one step up
  EXPECT_DOUBLE_EQ(selector.last().last_ratio, 0.1);
  const auto& unmeasured = selector.select(view, -1.0);
  EXPECT_EQ(unmeasured.n, lower) << "no measurement keeps the size";
  EXPECT_DOUBLE_EQ(unmeasured.last_ratio, 0.1) << "and the last ratio";
}

TEST(TwoLevelSelection, Level1KeepsItsSquareUntilTheNewHeightsAreResident) {
  const World world;
  ig::options::TwoLevelOptions options;
  options.level0_budget = 2048;
  auto selector = world.selector(options);
  bool resident = true;
  int asked = 0;
  ig::lod::Level1Paging paging{true, [&](glm::ivec2, glm::ivec2, glm::ivec2) {
                                 ++asked;
                                 return resident;
                               }};
  const auto here = view_at(world.hf, 100, 100, 300.0, 45.0, -60.0);
  const auto there = view_at(world.hf, 400, 420, 300.0, 45.0, -60.0);
  selector.select(here, -1.0, paging);  // the first frame may wait: not asked
  EXPECT_EQ(asked, 0);
  const auto& first = selector.select(here, -1.0, paging);
  ASSERT_FALSE(first.held);
  const glm::ivec2 origin = first.origin;
  const int n = first.n;

  resident = false;
  for (int frame = 0; frame < 3; ++frame) {
    const auto& sel = selector.select(there, -1.0, paging);
    EXPECT_TRUE(sel.held) << "frame " << frame;
    EXPECT_EQ(sel.origin, origin);
    EXPECT_EQ(sel.n, n);
    // The frame still asks for the held square's tiles and keeps the window on it.
    EXPECT_EQ(sel.scene_requests.window_centre, origin + (n - 1) / 2);
  }
  resident = true;
  const auto& moved = selector.select(there, -1.0, paging);
  EXPECT_FALSE(moved.held);
  EXPECT_TRUE(holds(moved, {400, 420}) || glm::length(glm::dvec2(moved.origin + moved.n / 2 - glm::ivec2(400, 420))) < moved.n);
  EXPECT_GT(asked, 3);
}

TEST(TwoLevelSelection, WallsFollowThePerimeter) {
  const World world;
  ig::options::TwoLevelOptions options;
  options.level0_budget = 2048;
  auto selector = world.selector(options);
  const auto& sel = selector.select(view_at(world.hf, 200, 200, 300.0, 45.0, -45.0), -1.0);
  ASSERT_FALSE(sel.visible_blocks.empty());
  ASSERT_EQ(sel.wall_z.size(), 2 * ig::lod::level1_perimeter(sel.n).size());
  for (size_t k = 0; k < sel.wall_z.size(); k += 2) EXPECT_GT(sel.wall_z[k].y, sel.wall_z[k + 1].y);
  EXPECT_EQ(ig::lod::level1_perimeter(33).size(), 4u * 32u);
}

// Level0's height at an edge sample is a search, so only the stretches of
// the edge the view may see get walls; the rest have walls of no height,
// filled when the view turns to them while the square stays put.
TEST(TwoLevelSelection, WallsAreFilledWhereTheViewMaySeeThem) {
  const World world;
  ig::options::TwoLevelOptions options;
  options.level0_budget = 2048;
  auto selector = world.selector(options);
  auto view = view_at(world.hf, 200, 200, 300.0, 45.0, -30.0);
  // In view: a box with a corner in front of the eye (a half-space, conservative).
  const glm::dvec3 forward = view.forward;
  view.box_in_view = [forward](const glm::dvec3& lo, const glm::dvec3& hi) {
    for (int c = 0; c < 8; ++c)
      if (glm::dot(glm::dvec3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z), forward) > 0.0) return true;
    return false;
  };
  const auto& sel = selector.select(view, 0.5);
  ASSERT_FALSE(sel.visible_blocks.empty());
  const auto perimeter = ig::lod::level1_perimeter(sel.n);
  auto exact = [&](size_t k) {
    const glm::ivec2 s = sel.origin + perimeter[k];
    const float h1 = world.hf.at_clamped(s.x, s.y);
    const double q = selector.level0_heights().height_at(s.x, s.y);
    const float h0 = std::isfinite(q) ? float(q) : h1;
    return std::pair<float, float>{std::max(h0, h1), std::min(h0, h1) - 1.0f};
  };
  auto in_front = [&](size_t k) {
    const glm::ivec2 s = sel.origin + perimeter[k];
    return glm::dot(glm::dvec2(s.x * world.hf.spacing_x_m, s.y * world.hf.spacing_y_m) - glm::dvec2(view.position),
                    glm::dvec2(forward)) > 0.0;
  };
  int filled = 0, empty = 0;
  for (size_t k = 0; k < perimeter.size(); ++k) {
    const auto [top, bottom] = exact(k);
    if (sel.wall_z[2 * k].y == sel.wall_z[2 * k + 1].y) {
      ++empty;
      EXPECT_FALSE(in_front(k)) << "sample " << k << ": in front of the eye without a wall";
    } else {
      ++filled;
      EXPECT_EQ(sel.wall_z[2 * k].y, top) << "sample " << k;
      EXPECT_EQ(sel.wall_z[2 * k + 1].y, bottom) << "sample " << k;
    }
  }
  std::printf("[twolevel_selection] walls filled at %d of %zu edge samples\n", filled, perimeter.size());
  EXPECT_GT(filled, 0);
  EXPECT_GT(empty, 0);

  // The same square seen whole: every stretch filled, and a new version to upload.
  const auto version = sel.wall_version;
  const glm::ivec2 origin = sel.origin;
  view.box_in_view = [](const glm::dvec3&, const glm::dvec3&) { return true; };
  const auto& whole = selector.select(view, 0.5);
  ASSERT_EQ(whole.origin, origin);
  EXPECT_NE(whole.wall_version, version);
  for (size_t k = 0; k < perimeter.size(); ++k) {
    const auto [top, bottom] = exact(k);
    EXPECT_EQ(whole.wall_z[2 * k].y, top) << "sample " << k;
    EXPECT_EQ(whole.wall_z[2 * k + 1].y, bottom) << "sample " << k;
  }
  // Nothing new to fill: the version stays (nothing is uploaded again).
  const auto again = selector.select(view, 0.5).wall_version;
  EXPECT_EQ(again, whole.wall_version);
}

// The walls are kept while the square stays put and made again when it
// moves or resizes: after every frame of a flight they are the heights of
// the square the frame selected.
TEST(TwoLevelSelection, WallsAreThoseOfTheSquareOfEveryFrame) {
  const World world;
  ig::options::TwoLevelOptions options;
  options.level0_budget = 2048;
  auto selector = world.selector(options);
  int kept = 0, moved = 0;
  glm::ivec2 last_origin{-1};
  int last_n = 0;
  for (int frame = 0; frame < 60; ++frame) {
    // Slow (a fraction of a sample a frame), then a turn that moves E far.
    const double heading = frame < 40 ? 45.0 : 135.0;
    const auto& sel = selector.select(view_at(world.hf, 200 + 0.3 * frame, 200, 300.0, heading, -30.0), 0.5);
    if (sel.visible_blocks.empty()) continue;
    (sel.origin == last_origin && sel.n == last_n ? kept : moved) += 1;
    last_origin = sel.origin;
    last_n = sel.n;
    const auto perimeter = ig::lod::level1_perimeter(sel.n);
    ASSERT_EQ(sel.wall_z.size(), 2 * perimeter.size()) << "frame " << frame;
    for (size_t k = 0; k < perimeter.size(); ++k) {
      const glm::ivec2 s = sel.origin + perimeter[k];
      const float h1 = world.hf.at_clamped(s.x, s.y);
      const double q = selector.level0_heights().height_at(s.x, s.y);
      const float h0 = std::isfinite(q) ? float(q) : h1;
      ASSERT_EQ(sel.wall_z[2 * k].y, std::max(h0, h1)) << "frame " << frame << " sample " << k;
      ASSERT_EQ(sel.wall_z[2 * k + 1].y, std::min(h0, h1) - 1.0f) << "frame " << frame << " sample " << k;
    }
  }
  EXPECT_GT(kept, 10);
  EXPECT_GT(moved, 1);
}

}  // namespace
