// Horizon culling: floors never above what is drawn, and a box marked hidden
// has no point the eye could see (every line to it crosses the terrain
// first), checked with the exact ray cast, with and without Earth curvature.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "lod/horizon_culling.h"
#include "lod/level0_height_query.h"
#include "lod/roam_level0_mesh.h"
#include "lod/terrain_floors.h"
#include "lod_test_terrain.h"
#include "terrain/earth_curvature.h"
#include "terrain/height_pyramid.h"
#include "terrain/ray_cast.h"

namespace {

using ig::lod::HorizonCulling;

TEST(TerrainFloors, NeverAboveTheDemNorLevel0) {
  const auto hf = lod_checks::synthetic(257, 7);
  const ig::terrain::HeightPyramid pyramid(hf);
  const auto level0 = ig::lod::build_level0_mesh(hf, {2048});
  const ig::lod::Level0HeightQuery level0_height(level0, hf.width, hf.height);
  const auto floors = ig::lod::terrain_floors(level0, pyramid, 4);
  ASSERT_EQ(floors.cell_samples, 16);
  ASSERT_EQ(floors.nx, 16);
  auto floor_at = [&](double i, double j) {
    // A point on a cell edge belongs to both cells: the lower floor holds.
    float f = 1e30f;
    for (int di = -1; di <= 0; ++di)
      for (int dj = -1; dj <= 0; ++dj) {
        const int ci = std::clamp(int(std::floor((i + di * 1e-9) / 16)), 0, floors.nx - 1);
        const int cj = std::clamp(int(std::floor((j + dj * 1e-9) / 16)), 0, floors.ny - 1);
        f = std::min(f, floors.at(ci, cj));
      }
    return f;
  };
  for (int j = 0; j < hf.height; ++j)
    for (int i = 0; i < hf.width; ++i) ASSERT_LE(floor_at(i, j), hf.at(i, j)) << i << ", " << j;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.0, 256.0);
  double tightest = 1e30;
  for (int k = 0; k < 20000; ++k) {
    const double i = u(rng), j = u(rng);
    const double h = level0_height.height_at(i, j);
    ASSERT_LE(floor_at(i, j), h + 1e-3) << i << ", " << j;
    tightest = std::min(tightest, h - floor_at(i, j));
  }
  EXPECT_LT(tightest, 5.0) << "floors far below everything: culling would never help";
}

// Every Level0 triangle's chord (its box's diagonal, in samples) is at most
// the chord of each cell its box touches, so the sag bound covers it.
TEST(TerrainFloors, ChordCoversEveryTriangleOverTheCell) {
  const auto hf = lod_checks::synthetic(257, 7);
  const ig::terrain::HeightPyramid pyramid(hf);
  const auto level0 = ig::lod::build_level0_mesh(hf, {2048});
  const auto floors = ig::lod::terrain_floors(level0, pyramid, 4);
  ASSERT_EQ(floors.chord_samples.size(), floors.floor_m.size());
  float longest = 0.0f;
  for (size_t t = 0; t + 2 < level0.indices.size(); t += 3) {
    glm::ivec2 lo(1 << 30), hi(-(1 << 30));
    for (int k = 0; k < 3; ++k) {
      lo = glm::min(lo, level0.samples[level0.indices[t + k]]);
      hi = glm::max(hi, level0.samples[level0.indices[t + k]]);
    }
    const auto chord = float(std::hypot(double(hi.x - lo.x), double(hi.y - lo.y)));
    longest = std::max(longest, chord);
    for (int j = lo.y / 16; j <= std::min(hi.y / 16, floors.ny - 1); ++j)
      for (int i = lo.x / 16; i <= std::min(hi.x / 16, floors.nx - 1); ++i)
        ASSERT_GE(floors.chord_samples[size_t(j) * floors.nx + i], chord) << "cell " << i << ", " << j;
  }
  EXPECT_GT(longest, 16.0f) << "a 2048-triangle Level0 has triangles larger than a cell";
}

// A 2 km-high wall across a flat plain: what is behind and below its crest
// is hidden, what is in front of it or above the line over the crest is not.
TEST(HorizonCulling, WallHidesWhatIsBehindIt) {
  const auto hf = lod_checks::heightfield_from(257, 257, 10.0, 10.0,
                                               [](int i, int) { return i >= 104 && i <= 144 ? 2000.0 : 0.0; });
  const ig::terrain::HeightPyramid pyramid(hf);
  const auto level0 = ig::lod::build_level0_mesh(hf, {8192});
  HorizonCulling culling(ig::lod::terrain_floors(level0, pyramid, 3), {10.0, 10.0});
  const glm::dvec3 eye(500.0, 1280.0, 100.0);  // 540 m in front of the 400 m-thick wall, 100 m up
  std::vector<HorizonCulling::Box> boxes = {
      {{1600, 1200, 0}, {1700, 1300, 500}},     // behind the wall, low: hidden
      {{800, 1200, 0}, {900, 1300, 500}},       // in front of it: seen
      {{2200, 1200, 0}, {2300, 1300, 10000}},   // behind it, but above the line over the crest
      {{1600, 0, 0}, {1700, 100, 10}},          // behind it, off to the side: still under the wall's line
  };
  std::vector<std::uint8_t> hidden;
  EXPECT_EQ(culling.mark_hidden(eye, 0.0, 5.0, boxes, hidden), 2);
  EXPECT_EQ(hidden, (std::vector<std::uint8_t>{1, 0, 0, 1}));
}

// Random eyes and cluster-sized boxes over a rough terrain: every point of
// every hidden box is behind the terrain (the exact ray cast from the eye
// hits before it), and the culling hides a good share of them.
// bins_per_whole_cell: how soon the sweep takes coarser cells (lowest of 2 x 2);
// min_share: the share of boxes hidden at least.
void check_hidden_boxes_are_hidden(double earth_radius_m, double bins_per_whole_cell = 32.0, double min_share = 0.1) {
  const auto hf = lod_checks::synthetic(513, 9);
  const ig::terrain::HeightPyramid pyramid(hf);
  const auto level0 = ig::lod::build_level0_mesh(hf, {8192});
  const ig::lod::Level0HeightQuery level0_height(level0, hf.width, hf.height);
  HorizonCulling culling(ig::lod::terrain_floors(level0, pyramid, 4), {hf.spacing_x_m, hf.spacing_y_m},
                         bins_per_whole_cell);
  std::mt19937 rng(earth_radius_m > 0 ? 4 : 3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double side = (hf.width - 1) * hf.spacing_x_m;
  long long boxes_total = 0, boxes_hidden = 0, points_checked = 0;
  for (int view = 0; view < 40; ++view) {
    glm::dvec3 eye(side * (0.1 + 0.8 * u(rng)), side * (0.1 + 0.8 * u(rng)), 0.0);
    const double i = eye.x / hf.spacing_x_m, j = eye.y / hf.spacing_y_m;
    eye.z = std::max(hf.sample_bilinear(eye.x, eye.y), level0_height.height_at(i, j)) + 20.0 + 400.0 * u(rng) * u(rng);
    std::vector<HorizonCulling::Box> boxes;
    for (int b = 0; b < 300; ++b) {
      const int w = 4 + int(28 * u(rng)), h = 4 + int(28 * u(rng));
      const int x0 = int((hf.width - 1 - w) * u(rng)), y0 = int((hf.height - 1 - h) * u(rng));
      float lo = 1e30f, hi = -1e30f;
      for (int y = y0; y <= y0 + h; ++y)
        for (int x = x0; x <= x0 + w; ++x) {
          lo = std::min(lo, hf.at(x, y));
          hi = std::max(hi, hf.at(x, y));
        }
      boxes.push_back({{x0 * hf.spacing_x_m, y0 * hf.spacing_y_m, lo}, {(x0 + w) * hf.spacing_x_m, (y0 + h) * hf.spacing_y_m, hi}});
    }
    std::vector<std::uint8_t> hidden;
    boxes_hidden += culling.mark_hidden(eye, earth_radius_m, 5.0, boxes, hidden);
    boxes_total += long(boxes.size());
    const ig::terrain::Curvature curvature{eye.x, eye.y, earth_radius_m};
    for (size_t b = 0; b < boxes.size(); ++b) {
      if (!hidden[b]) continue;
      for (int p = 0; p < 40; ++p) {
        // Corners of the box's top and random points in it, as drawn (lowered by the curvature).
        glm::dvec3 point = p < 4 ? glm::dvec3(p & 1 ? boxes[b].hi.x : boxes[b].lo.x, p & 2 ? boxes[b].hi.y : boxes[b].lo.y,
                                               boxes[b].hi.z)
                                 : glm::mix(boxes[b].lo, boxes[b].hi, glm::dvec3(u(rng), u(rng), u(rng)));
        point.z -= ig::terrain::curvature_drop(std::hypot(point.x - eye.x, point.y - eye.y), earth_radius_m);
        const glm::dvec3 d = point - eye;
        const double length = glm::length(d);
        const auto hit = ig::terrain::cast_ray(hf, pyramid, eye, d / length, length, curvature);
        ASSERT_TRUE(hit && hit->t < length - 1e-3)
            << "view " << view << ", box " << b << ": a point marked hidden is in plain sight";
        ++points_checked;
      }
    }
  }
  std::printf("%lld of %lld boxes hidden, %lld of their points checked\n", boxes_hidden, boxes_total, points_checked);
  EXPECT_GT(double(boxes_hidden), min_share * double(boxes_total)) << "the culling should hide a share of boxes from low eyes";
}

TEST(HorizonCulling, HiddenBoxesHaveNoVisiblePoint) { check_hidden_boxes_are_hidden(0.0); }
TEST(HorizonCulling, HiddenBoxesHaveNoVisiblePointWithEarthCurvature) {
  check_hidden_boxes_are_hidden(30000.0);  // an exaggerated curve: 30 km radius
}
// Only the finest cells; the coarsest cells wherever the eye is not over them
// (lower floors, so fewer boxes are hidden, but still some).
TEST(HorizonCulling, HiddenBoxesHaveNoVisiblePointWithFinestCellsOnly) { check_hidden_boxes_are_hidden(0.0, 0.0); }
TEST(HorizonCulling, HiddenBoxesHaveNoVisiblePointWithCoarseCellsFarOut) {
  check_hidden_boxes_are_hidden(30000.0, 1e9, 0.005);
}

}  // namespace
