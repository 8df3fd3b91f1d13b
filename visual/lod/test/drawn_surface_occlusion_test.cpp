// Horizon culling over a method's own drawn boxes: a box marked hidden has no
// point the eye could see (the exact ray cast over the DEM hits first: the
// boxes' bottoms, the floors, are under the DEM), nothing is hidden while the
// eye is under a box it stands in, and a culled triangle list keeps its order.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "lod/drawn_surface_occlusion.h"
#include "lod_test_terrain.h"
#include "terrain/earth_curvature.h"
#include "terrain/height_pyramid.h"
#include "terrain/ray_cast.h"

namespace {

using ig::lod::DrawnSurfaceOcclusion;
using ig::lod::HorizonCulling;

// The DEM in square blocks of `step` samples, each box from its samples' heights.
std::vector<HorizonCulling::Box> blocks(const ig::terrain::Heightfield& hf, int step) {
  std::vector<HorizonCulling::Box> out;
  for (int y0 = 0; y0 < hf.height - 1; y0 += step)
    for (int x0 = 0; x0 < hf.width - 1; x0 += step) {
      const int x1 = std::min(x0 + step, hf.width - 1), y1 = std::min(y0 + step, hf.height - 1);
      float lo = 1e30f, hi = -1e30f;
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          lo = std::min(lo, hf.at(x, y));
          hi = std::max(hi, hf.at(x, y));
        }
      out.push_back({{x0 * hf.spacing_x_m, y0 * hf.spacing_y_m, lo}, {x1 * hf.spacing_x_m, y1 * hf.spacing_y_m, hi}});
    }
  return out;
}

// Every point sampled in a hidden box is behind the DEM seen from the eye.
void expect_really_hidden(const ig::terrain::Heightfield& hf, const ig::terrain::HeightPyramid& pyramid,
                          const glm::dvec3& eye, double earth_radius_m, const HorizonCulling::Box& box,
                          std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const ig::terrain::Curvature curvature{eye.x, eye.y, earth_radius_m};
  for (int p = 0; p < 24; ++p) {
    glm::dvec3 point = p < 4 ? glm::dvec3(p & 1 ? box.hi.x : box.lo.x, p & 2 ? box.hi.y : box.lo.y, box.hi.z)
                             : glm::mix(box.lo, box.hi, glm::dvec3(u(rng), u(rng), u(rng)));
    point.z -= ig::terrain::curvature_drop(std::hypot(point.x - eye.x, point.y - eye.y), earth_radius_m);
    const glm::dvec3 d = point - eye;
    const double length = glm::length(d);
    const auto hit = ig::terrain::cast_ray(hf, pyramid, eye, d / length, length, curvature);
    ASSERT_TRUE(hit && hit->t < length - 1e-3) << "a point marked hidden is in plain sight";
  }
}

// A side x side DEM, samples 10 m apart, flat at 0 m but for a 2000 m wall
// along columns first..last.
ig::terrain::Heightfield wall_dem(int side, int first, int last) {
  return lod_checks::heightfield_from(side, side, 10.0, 10.0,
                                      [=](int i, int) { return i >= first && i <= last ? 2000.0 : 0.0; });
}

// A 257^2 wall DEM (the wall 400 m thick, 1040 m east) in blocks of 16
// samples, and an eye in front of the wall, 100 m up.
struct WallAhead {
  const ig::terrain::Heightfield hf = wall_dem(257, 104, 144);
  const ig::terrain::HeightPyramid pyramid{hf};
  DrawnSurfaceOcclusion occlusion{hf, pyramid, 16};
  const std::vector<HorizonCulling::Box> boxes = blocks(hf, 16);
  const glm::dvec3 eye{500.0, 1280.0, 100.0};
};

TEST(DrawnSurfaceOcclusion, WallHidesTheBlocksBehindIt) {
  WallAhead w;
  auto& [hf, pyramid, occlusion, boxes, eye] = w;
  std::vector<std::uint8_t> hidden;
  const int count = occlusion.mark_hidden(eye, 0.0, 5.0, boxes, hidden, occlusion.dem_max_near(eye, 1));
  int behind = 0, behind_hidden = 0, in_front_hidden = 0;
  for (size_t k = 0; k < boxes.size(); ++k) {
    if (boxes[k].lo.x >= 1600.0) behind += 1, behind_hidden += hidden[k];
    if (boxes[k].hi.x <= 1000.0) in_front_hidden += hidden[k];
  }
  EXPECT_EQ(in_front_hidden, 0);
  EXPECT_EQ(behind, 6 * 16);
  EXPECT_EQ(behind_hidden, behind) << "the wall spans the whole view: every block behind its foot is hidden";
  EXPECT_EQ(count, std::count(hidden.begin(), hidden.end(), 1));
}

TEST(DrawnSurfaceOcclusion, NothingHiddenWhileTheEyeIsUnderTheDrawnSurface) {
  WallAhead w;
  auto& [hf, pyramid, occlusion, boxes, eye] = w;
  std::vector<std::uint8_t> hidden;
  // A coarse piece over the eye may draw above it (a triangle reaching a
  // higher sample): then the eye may be under the surface.
  EXPECT_EQ(occlusion.mark_hidden(eye, 0.0, 5.0, boxes, hidden, 150.0), 0);
  EXPECT_EQ(std::count(hidden.begin(), hidden.end(), 1), 0);
  EXPECT_GT(occlusion.mark_hidden(eye, 0.0, 5.0, boxes, hidden, 90.0), 0);
  // Within 65 samples of the eye lies the wall: that bound is over the eye.
  EXPECT_NEAR(occlusion.dem_max_near(eye, 65), 2000.0, 0.1);
  EXPECT_NEAR(occlusion.dem_max_near(eye, 4), 0.0, 0.1);
}

void check_random_views(double earth_radius_m) {
  const auto hf = lod_checks::synthetic(513, 9);
  const ig::terrain::HeightPyramid pyramid(hf);
  DrawnSurfaceOcclusion occlusion(hf, pyramid);
  std::mt19937 rng(earth_radius_m > 0 ? 6 : 5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double side = (hf.width - 1) * hf.spacing_x_m;
  long long total = 0, hidden_total = 0;
  for (int view = 0; view < 30; ++view) {
    glm::dvec3 eye(side * (0.1 + 0.8 * u(rng)), side * (0.1 + 0.8 * u(rng)), 0.0);
    const int step = 8 << (view % 3);  // blocks of 8, 16, 32 samples
    const auto boxes = blocks(hf, step);
    const double over = occlusion.dem_max_near(eye, 1);  // the DEM under the eye
    eye.z = over + 10.0 + 300.0 * u(rng) * u(rng);
    std::vector<std::uint8_t> hidden;
    hidden_total += occlusion.mark_hidden(eye, earth_radius_m, 5.0, boxes, hidden, over);
    total += (long long)boxes.size();
    for (size_t b = 0; b < boxes.size(); ++b) {
      if (hidden[b]) {
        ASSERT_NO_FATAL_FAILURE(expect_really_hidden(hf, pyramid, eye, earth_radius_m, boxes[b], rng));
      }
    }
  }
  std::printf("%lld of %lld blocks hidden\n", hidden_total, total);
  EXPECT_GT(hidden_total, total / 20) << "low eyes over rough terrain should see past few blocks";
}

TEST(DrawnSurfaceOcclusion, HiddenBlocksHaveNoVisiblePoint) { check_random_views(0.0); }
TEST(DrawnSurfaceOcclusion, HiddenBlocksHaveNoVisiblePointWithEarthCurvature) { check_random_views(30000.0); }

TEST(DrawnSurfaceOcclusion, CulledTriangleListKeepsItsOrder) {
  const auto hf = wall_dem(129, 52, 72);
  const ig::terrain::HeightPyramid pyramid(hf);
  std::vector<glm::u16vec2> all;  // the full grid, two triangles a cell
  for (int j = 0; j < hf.height - 1; ++j)
    for (int i = 0; i < hf.width - 1; ++i) {
      const glm::u16vec2 a(i, j), b(i + 1, j), c(i + 1, j + 1), d(i, j + 1);
      all.insert(all.end(), {a, b, c, a, c, d});
    }
  DrawnSurfaceOcclusion occlusion(hf, pyramid, 8);
  auto kept = all;
  const glm::dvec3 eye(250.0, 640.0, 60.0);
  EXPECT_GT(occlusion.cull_triangles(eye, 0.0, 5.0, kept), 0);
  ASSERT_LT(kept.size(), all.size());
  ASSERT_EQ(kept.size() % 3, 0u);
  // A subsequence of the original, whole triangles; every one left out is hidden.
  std::mt19937 rng(7);
  size_t k = 0;
  for (size_t t = 0; t < all.size(); t += 3) {
    if (k < kept.size() && kept[k] == all[t] && kept[k + 1] == all[t + 1] && kept[k + 2] == all[t + 2]) {
      k += 3;
      continue;
    }
    HorizonCulling::Box box{glm::dvec3(1e30), glm::dvec3(-1e30)};
    for (int v = 0; v < 3; ++v) {
      const glm::dvec3 p(all[t + v].x * 10.0, all[t + v].y * 10.0, hf.at(all[t + v].x, all[t + v].y));
      box.lo = glm::min(box.lo, p);
      box.hi = glm::max(box.hi, p);
    }
    ASSERT_NO_FATAL_FAILURE(expect_really_hidden(hf, pyramid, eye, 0.0, box, rng));
  }
  EXPECT_EQ(k, kept.size()) << "the kept triangles are not in their original order";
}

}  // namespace
