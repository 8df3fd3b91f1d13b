// Restricted quadtree LOD (lod/quadtree_tessellator, quadtree_nodes):
// adjacent leaves differ by at most one level, crack-free output, honest fan
// errors and error bound, C1 monotonicity, roughness propagation, culling,
// bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "lod/quadtree_nodes.h"
#include "lod/quadtree_tessellator.h"
#include "lod_mesh_checks.h"

namespace {

using ig::lod::QuadtreeTessellator;
using lod_checks::eyes_for;
using ig::terrain::Heightfield;

constexpr double kC2 = 30.0;  // the method's default

// Leaves sharing an edge differ by at most one level.
std::string level_problem(const QuadtreeTessellator& q, const Heightfield& hf) {
  for (int cy = 0; cy < hf.height - 1; ++cy)
    for (int cx = 0; cx < hf.width - 1; ++cx) {
      const int l = q.leaf_level(cx, cy);
      if (l < 0) return "cell outside the quadtree";
      if (cx + 1 < hf.width - 1 && std::abs(l - q.leaf_level(cx + 1, cy)) > 1)
        return "levels differ by more than 1 at cell " + std::to_string(cx) + "," + std::to_string(cy);
      if (cy + 1 < hf.height - 1 && std::abs(l - q.leaf_level(cx, cy + 1)) > 1)
        return "levels differ by more than 1 at cell " + std::to_string(cx) + "," + std::to_string(cy);
    }
  return "";
}

TEST(QuadtreeTessellator, LeavesDifferByAtMostOneLevelAndTheMeshIsWatertight) {
  std::vector<Heightfield> dems = lod_checks::dems_of_many_sizes();
  dems.push_back(lod_checks::synthetic(129, 7));
  long long forced = 0, splits = 0;
  for (const auto& hf : dems) {
    QuadtreeTessellator q(hf);
    for (const auto& eye : eyes_for(hf))
      for (double c1 : {0.5, 2.0, 8.0, 32.0, 1000.0}) {
        const auto sel = q.select(eye, c1, kC2);
        const std::string where = std::to_string(hf.width) + "x" + std::to_string(hf.height) + " C1 " +
                                  std::to_string(c1) + " eye " + std::to_string(eye.x) + "," + std::to_string(eye.y);
        EXPECT_EQ(level_problem(q, hf), "") << where;
        EXPECT_EQ(lod_checks::watertight(sel.vertices, hf.width, hf.height), "") << where;
        EXPECT_EQ(sel.stats.triangles * 3, (long long)sel.vertices.size());
        forced += sel.stats.forced_splits;
        splits += sel.stats.splits;
      }
  }
  std::printf("restriction forced %lld splits besides %lld by f < 1\n", forced, splits);
  EXPECT_GT(splits, 0);
}

TEST(QuadtreeTessellator, RestrictionForcesSplitsWhereTheCriterionAloneWouldCrack) {
  // On a plane (DHmax = 0) the criterion is L < d * C1: for C1 below ~1.6 a
  // node can split while the coarser neighbour of its children does not
  // (docs/baselines.md). The restriction pass must step in and still leave a
  // watertight mesh with levels differing by at most one.
  const auto hf =
      lod_checks::heightfield_from(129, 129, 30.0, 30.0, [](int i, int j) { return 500.0 + 2.0 * i + 1.0 * j; });
  QuadtreeTessellator q(hf);
  long long forced = 0;
  for (const auto& eye : eyes_for(hf))
    for (double c1 : {0.3, 0.6, 1.0}) {
      const auto sel = q.select(eye, c1, kC2);
      forced += sel.stats.forced_splits;
      EXPECT_EQ(level_problem(q, hf), "");
      EXPECT_EQ(lod_checks::watertight(sel.vertices, hf.width, hf.height), "");
      EXPECT_EQ(sel.stats.max_error_ratio, 0.0) << "a plane has no geometric error";
    }
  EXPECT_GT(forced, 0);
}

TEST(QuadtreeNodes, FanErrorBoundsTheReferenceSurfaceAndRoughnessIsPropagated) {
  for (const auto& hf : {lod_checks::synthetic(33), lod_checks::cropped(40, 23)}) {
    const auto nodes = ig::lod::compute_quadtree_nodes(hf);
    int checked = 0;
    for (int k = 0; k < nodes.levels; ++k) {
      const int h = 1 << k;
      for (int b = 0; b < nodes.ny[k]; ++b)
        for (int a = 0; a < nodes.nx[k]; ++a) {
          const int ci = (2 * a + 1) * h, cj = (2 * b + 1) * h;
          const auto n = nodes.index(k, a, b);
          if (k > 0) {
            // Röttger: parent >= child; seed: >= the half-size nodes just outside.
            for (int j = 2 * b - 1; j <= 2 * b + 2; ++j)
              for (int i = 2 * a - 1; i <= 2 * a + 2; ++i) {
                const bool corner = (i == 2 * a - 1 || i == 2 * a + 2) && (j == 2 * b - 1 || j == 2 * b + 2);
                if (corner || i < 0 || j < 0 || i >= nodes.nx[k - 1] || j >= nodes.ny[k - 1]) continue;
                ASSERT_GE(nodes.roughness[n], nodes.roughness[nodes.index(k - 1, i, j)]);
              }
          }
          if (ci + h > hf.width - 1 || cj + h > hf.height - 1) continue;  // only nodes inside the DEM
          const glm::ivec2 c(ci, cj);
          const glm::ivec2 ring[8] = {{ci - h, cj - h}, {ci, cj - h}, {ci + h, cj - h}, {ci + h, cj},
                                      {ci + h, cj + h}, {ci, cj + h}, {ci - h, cj + h}, {ci - h, cj}};
          double worst = 0.0;
          for (int m = 0; m < 8; ++m)
            worst = std::max(worst, lod_checks::triangle_deviation(hf, c, ring[m], ring[(m + 1) % 8]).metres);
          ASSERT_LE(worst, nodes.fan_error[n] + 1e-3) << "node " << k << "," << a << "," << b;
          ++checked;
        }
    }
    EXPECT_GT(checked, 50);
  }
}

TEST(QuadtreeTessellator, ErrorBoundCoversEveryOutputPoint) {
  lod_checks::expect_bound_covers_every_output_point<QuadtreeTessellator>(
      {lod_checks::synthetic(65), lod_checks::cropped(50, 41)}, {1.0, 8.0}, "C1",
      [](QuadtreeTessellator& q, const glm::dvec3& eye, double c1) { return q.select(eye, c1, kC2); });
}

TEST(QuadtreeTessellator, LargerC1GivesMoreTrianglesAndASmallerBound) {
  lod_checks::expect_more_triangles_and_no_larger_bound<QuadtreeTessellator>(
      {1.0, 2.0, 4.0, 8.0, 16.0}, "C1",
      [](QuadtreeTessellator& q, const glm::dvec3& eye, double c1) { return q.select(eye, c1, kC2); });
}

TEST(QuadtreeTessellator, CulledNodesAreNotSplit) {
  const lod_checks::EastOfEyeCulling<QuadtreeTessellator> culling(
      [](QuadtreeTessellator& q, const glm::dvec3& eye, const ig::lod::BoxInView& in_view) {
        return q.select(eye, 8.0, kC2, in_view);
      });
  const auto& [hf, q, eye, all, sel] = culling;
  EXPECT_LT(sel.stats.evaluated, all.evaluated * 3 / 4);
  EXPECT_EQ(level_problem(q, hf), "");
  // Culling is per node: every drawn fan triangle's node (centre = first
  // vertex, half-size = its largest offset from it) reaches east of the eye.
  const auto& v = sel.vertices;
  for (size_t t = 0; t < v.size(); t += 3) {
    const glm::ivec2 c(v[t]), p(v[t + 1]), r(v[t + 2]);
    const int half = std::max({std::abs(p.x - c.x), std::abs(p.y - c.y), std::abs(r.x - c.x), std::abs(r.y - c.y)});
    ASSERT_GE((c.x + half) * hf.spacing_x_m, eye.x) << "a node wholly west of the eye was drawn";
  }
}

TEST(QuadtreeTessellator, RejectsBadInput) {
  lod_checks::expect_rejects_bad_input<QuadtreeTessellator>(4, 1, [](QuadtreeTessellator& q) {
    EXPECT_THROW(q.select({0, 0, 100}, 0.0, kC2), std::invalid_argument);
    EXPECT_THROW(q.select({0, 0, 100}, 4.0, -1.0), std::invalid_argument);
    EXPECT_THROW(q.select({0, 0, 100}, std::nan(""), kC2), std::invalid_argument);
    EXPECT_THROW(q.select({0, std::nan(""), 100}, 4.0, kC2), std::invalid_argument);
  });
}

}  // namespace
