// View-dependent ROAM (lod/roam_tessellator, roam_wedgie_grid, roam_patch_grid):
// crack-free output for many eyes, sizes and tolerances, honest wedgies and
// error bound, tolerance monotonicity, culling, bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include "lod/roam_patch_grid.h"
#include "lod/roam_tessellator.h"
#include "lod/roam_wedgie_grid.h"
#include "lod_mesh_checks.h"

namespace {

using ig::lod::RoamTessellator;
using lod_checks::eyes_for;
using ig::terrain::Heightfield;

constexpr double kPixelsPerRadian = 887.0;  // 1024 px tall, 60 degrees

TEST(RoamPatchGrid, CoversAnySizeWithLittleOverhang) {
  for (auto [w, h] : {std::pair{1025, 1025}, {4097, 4097}, {1201, 1201}, {65, 65}, {2, 2}, {3, 9}, {1000, 700}}) {
    const auto g = ig::lod::make_patch_grid(w, h);
    EXPECT_GE(g.padded_x(), w - 1);
    EXPECT_GE(g.padded_y(), h - 1);
    EXPECT_EQ(g.patch & (g.patch - 1), 0) << "patch side must be a power of two";
    if (g.patch > 64) {
      EXPECT_LE(double(g.padded_x()) * g.padded_y(), 1.3 * (w - 1) * (h - 1)) << w << "x" << h;
    }
  }
  EXPECT_EQ(ig::lod::make_patch_grid(1025, 1025).patch, 1024);
  EXPECT_EQ(ig::lod::make_patch_grid(1201, 1201).patch, 256);  // 5 x 5 patches, 14 % overhang
  EXPECT_THROW(ig::lod::make_patch_grid(1, 5), std::invalid_argument);
}

TEST(RoamPatchGrid, ClippingKeepsIntegerSamplesAndArea) {
  // A 45-degree triangle over the corner (10, 10): what is left is the square [8, 10]^2.
  glm::ivec2 out[3][3];
  const int n = ig::lod::clip_to_dem({8, 8}, {12, 8}, {8, 12}, 10, 10, out);
  long long twice = 0;
  for (int k = 0; k < n; ++k) {
    const auto a = out[k][0], b = out[k][1], c = out[k][2];
    twice += (long long)(b.x - a.x) * (c.y - a.y) - (long long)(b.y - a.y) * (c.x - a.x);
    for (const auto& p : out[k]) EXPECT_TRUE(p.x <= 10 && p.y <= 10);
  }
  EXPECT_EQ(twice, 2 * 4);
  EXPECT_EQ(ig::lod::clip_to_dem({11, 0}, {13, 0}, {11, 2}, 10, 10, out), 0);  // wholly outside
}

TEST(RoamTessellator, OutputIsWatertightForManyViewsSizesAndTolerances) {
  for (const auto& hf : lod_checks::dems_of_many_sizes()) {
    RoamTessellator roam(hf);
    for (const auto& eye : eyes_for(hf))
      for (double tau : {0.0, 0.5, 2.0, 8.0, 1000.0}) {
        const auto sel = roam.select(eye, tau, kPixelsPerRadian);
        const std::string problem = lod_checks::watertight(sel.vertices, hf.width, hf.height);
        EXPECT_EQ(problem, "") << hf.width << "x" << hf.height << " tau " << tau << " eye " << eye.x << ","
                               << eye.y << "," << eye.z;
        EXPECT_EQ(sel.stats.triangles * 3, (long long)sel.vertices.size());
      }
  }
}

TEST(RoamTessellator, ForcedSplitsHappenAndKeepTheMeshWatertight) {
  const auto hf = lod_checks::synthetic(129);
  RoamTessellator roam(hf);
  const auto sel = roam.select({0.3 * hf.extent_x_m(), 0.6 * hf.extent_y_m(), hf.max_m + 20.0}, 1.0, kPixelsPerRadian);
  EXPECT_GT(sel.stats.forced_splits, 0);
  EXPECT_LT(sel.stats.forced_splits, sel.stats.splits);
  EXPECT_EQ(lod_checks::watertight(sel.vertices, hf.width, hf.height), "");
}

// Every bintree triangle's plane stays within its diamond's wedgie of the
// reference surface (checked at every sample and cell centre it covers).
void check_wedgies(const Heightfield& hf) {
  const auto grid = ig::lod::make_patch_grid(hf.width, hf.height);
  const auto wedgies = ig::lod::compute_roam_wedgies(hf, grid);
  int checked = 0;
  std::function<void(glm::ivec2, glm::ivec2, glm::ivec2)> visit = [&](glm::ivec2 apex, glm::ivec2 l, glm::ivec2 r) {
    const glm::ivec2 s = l + r;
    if ((s.x & 1) || (s.y & 1)) return;
    const glm::ivec2 m = s / 2;
    const glm::ivec2 mx = glm::max(apex, glm::max(l, r));
    if (mx.x <= hf.width - 1 && mx.y <= hf.height - 1) {  // wholly inside: the bound is e itself
      const double dev = lod_checks::triangle_deviation(hf, apex, l, r).metres;
      ASSERT_LE(dev, wedgies.at(m.x, m.y) + 1e-3) << "triangle with midpoint " << m.x << "," << m.y;
      ++checked;
    }
    visit(m, apex, l);
    visit(m, r, apex);
  };
  const int P = grid.patch;
  for (int py = 0; py < grid.ny; ++py)
    for (int px = 0; px < grid.nx; ++px) {
      const int x0 = px * P, y0 = py * P;
      visit({x0 + P, y0}, {x0 + P, y0 + P}, {x0, y0});
      visit({x0, y0 + P}, {x0, y0}, {x0 + P, y0 + P});
    }
  EXPECT_GT(checked, hf.width * hf.height / 2);
}

TEST(RoamWedgies, BoundTheReferenceSurfaceOverEveryTriangle) {
  check_wedgies(lod_checks::synthetic(33));
  check_wedgies(lod_checks::cropped(40, 23));
}

TEST(RoamTessellator, ErrorBoundCoversEveryOutputPoint) {
  // End to end: for every output triangle, its largest deviation from the
  // reference over the distance of that point from the eye is within the
  // claimed max_error_ratio.
  lod_checks::expect_bound_covers_every_output_point<RoamTessellator>(
      {lod_checks::synthetic(65), lod_checks::cropped(50, 41)}, {0.5, 4.0}, "tau",
      [](RoamTessellator& roam, const glm::dvec3& eye, double tau) { return roam.select(eye, tau, kPixelsPerRadian); });
}

TEST(RoamTessellator, SmallerToleranceGivesMoreTrianglesAndASmallerBound) {
  lod_checks::expect_more_triangles_and_no_larger_bound<RoamTessellator>(
      {16.0, 8.0, 4.0, 2.0, 1.0}, "tau",
      [](RoamTessellator& t, const glm::dvec3& eye, double tau) { return t.select(eye, tau, kPixelsPerRadian); });
}

TEST(RoamTessellator, PlanesNeedOnlyTheRootTriangles) {
  const auto hf =
      lod_checks::heightfield_from(65, 65, 10.0, 10.0, [](int i, int j) { return 100.0 + 0.3 * i - 0.7 * j; });
  RoamTessellator roam(hf);
  const auto s = roam.select({320, 320, 150}, 0.0, kPixelsPerRadian).stats;
  EXPECT_EQ(s.triangles, 2);
  EXPECT_EQ(s.max_error_ratio, 0.0);
}

TEST(RoamTessellator, CulledSubtreesAreNotRefined) {
  // Whole, and with a "view" of everything east of the eye only.
  const lod_checks::EastOfEyeCulling<RoamTessellator> culling(
      [](RoamTessellator& roam, const glm::dvec3& eye, const ig::lod::BoxInView& in_view) {
        return roam.select(eye, 1.0, kPixelsPerRadian, in_view);
      });
  const auto& [hf, roam, eye, all, sel] = culling;
  EXPECT_LT(sel.stats.nodes, all.nodes * 3 / 4);
  const auto& v = sel.vertices;
  for (size_t t = 0; t < v.size(); t += 3) {
    const double max_x = std::max({v[t].x, v[t + 1].x, v[t + 2].x}) * hf.spacing_x_m;
    ASSERT_GE(max_x, eye.x) << "a triangle wholly west of the eye was drawn";
  }
}

TEST(RoamTessellator, RejectsBadInput) {
  lod_checks::expect_rejects_bad_input<RoamTessellator>(1, 4, [](RoamTessellator& roam) {
    EXPECT_THROW(roam.select({0, 0, 100}, -1.0, kPixelsPerRadian), std::invalid_argument);
    EXPECT_THROW(roam.select({0, 0, 100}, std::nan(""), kPixelsPerRadian), std::invalid_argument);
    EXPECT_THROW(roam.select({std::nan(""), 0, 100}, 1.0, kPixelsPerRadian), std::invalid_argument);
  });
}

}  // namespace
