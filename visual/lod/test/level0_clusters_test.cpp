// Level0 clusters: the per-frame selection of the static buffer is exact
// against Level1's square and conservative against the view.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "lod/level0_clusters.h"
#include "lod/roam_level0_mesh.h"
#include "lod_test_terrain.h"

namespace {

using ig::lod::IndexRuns;
using ig::lod::Level0Clusters;

struct Tri {
  glm::ivec2 lo, hi;
};

std::vector<Tri> triangle_boxes(const ig::lod::Level0Mesh& m) {
  std::vector<Tri> out;
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    Tri b{glm::ivec2(1 << 30), glm::ivec2(-(1 << 30))};
    for (int k = 0; k < 3; ++k) {
      const auto s = m.samples[m.indices[t + k]];
      b.lo = {std::min(b.lo.x, s.x), std::min(b.lo.y, s.y)};
      b.hi = {std::max(b.hi.x, s.x), std::max(b.hi.y, s.y)};
    }
    out.push_back(b);
  }
  return out;
}

// Which class each triangle was put in: -1 not drawn, 0 outside, 1 crossing.
std::vector<int> classes(const IndexRuns& outside, const IndexRuns& crossing, size_t triangles) {
  std::vector<int> c(triangles, -1);
  for (int k = 0; k < 2; ++k) {
    const IndexRuns& r = k == 0 ? outside : crossing;
    for (size_t i = 0; i < r.first.size(); ++i) {
      EXPECT_EQ(r.first[i] % 3, 0u);
      EXPECT_EQ(r.count[i] % 3, 0u);
      for (auto t = r.first[i] / 3; t < (r.first[i] + r.count[i]) / 3; ++t) {
        EXPECT_EQ(c[t], -1) << "triangle " << t << " drawn twice";
        c[t] = k;
      }
    }
  }
  return c;
}

TEST(Level0Clusters, EveryTriangleInItsClassAgainstTheSquare) {
  const auto hf = lod_checks::synthetic(257);
  const auto mesh = ig::lod::z_ordered(ig::lod::build_level0_mesh(hf, {4096}));
  const Level0Clusters clusters(mesh, {hf.spacing_x_m, hf.spacing_y_m}, 64);
  EXPECT_EQ(clusters.cluster_count(), (mesh.triangle_count + 63) / 64);
  const auto boxes = triangle_boxes(mesh);
  for (const auto& [lo, hi] : std::vector<std::pair<glm::ivec2, glm::ivec2>>{
           {{96, 96}, {160, 160}}, {{0, 0}, {32, 32}}, {{200, 10}, {256, 74}}, {{-5, -5}, {300, 300}}}) {
    IndexRuns outside, crossing;
    const int culled = clusters.select(lo, hi, [](const glm::dvec3&, const glm::dvec3&) { return true; }, outside,
                                       crossing);
    EXPECT_EQ(culled, 0);
    const auto c = classes(outside, crossing, boxes.size());
    int drawn = 0;
    for (size_t t = 0; t < boxes.size(); ++t) {
      const auto& b = boxes[t];
      const bool inside = b.lo.x >= lo.x && b.lo.y >= lo.y && b.hi.x <= hi.x && b.hi.y <= hi.y;
      const bool clear = b.hi.x <= lo.x || b.lo.x >= hi.x || b.hi.y <= lo.y || b.lo.y >= hi.y;
      EXPECT_EQ(c[t], inside ? -1 : clear ? 0 : 1) << "triangle " << t;
      drawn += c[t] >= 0;
    }
    EXPECT_EQ(outside.indices() + crossing.indices(), std::uint64_t(3 * drawn));
  }
}

// The crossing clusters' runs are kept while the square stays put: the same
// square again (kept runs), another one and back (runs made anew), and a
// fresh object give the same runs.
TEST(Level0Clusters, RunsAreTheSameWhetherKeptOrMadeAnew) {
  const auto hf = lod_checks::synthetic(257);
  const auto mesh = ig::lod::z_ordered(ig::lod::build_level0_mesh(hf, {4096}));
  const Level0Clusters clusters(mesh, {hf.spacing_x_m, hf.spacing_y_m}, 64);
  const auto all = [](const glm::dvec3&, const glm::dvec3&) { return true; };
  const glm::ivec2 lo{93, 90}, hi{151, 157};  // off the mesh's power-of-two edges
  auto runs = [&](const Level0Clusters& c, glm::ivec2 a, glm::ivec2 b) {
    IndexRuns outside, crossing;
    c.select(a, b, all, outside, crossing);
    return std::vector<std::vector<std::uint32_t>>{outside.first, outside.count, crossing.first, crossing.count};
  };
  const auto first = runs(clusters, lo, hi);
  ASSERT_FALSE(first[2].empty()) << "the square should cross some triangles";
  EXPECT_EQ(runs(clusters, lo, hi), first);
  EXPECT_NE(runs(clusters, lo + 1, hi + 1), first);
  EXPECT_EQ(runs(clusters, lo, hi), first);
  EXPECT_EQ(runs(Level0Clusters(mesh, {hf.spacing_x_m, hf.spacing_y_m}, 64), lo, hi), first);
}

TEST(Level0Clusters, CullingKeepsEveryTriangleInTheVisibleRegionAndRunsAreMerged) {
  const auto hf = lod_checks::synthetic(257);
  const auto mesh = ig::lod::z_ordered(ig::lod::build_level0_mesh(hf, {8192}));
  const Level0Clusters clusters(mesh, {hf.spacing_x_m, hf.spacing_y_m}, 128);
  // "Visible": boxes reaching into the west quarter of the terrain.
  const double x_max = 64 * hf.spacing_x_m;
  IndexRuns outside, crossing;
  const int culled = clusters.select({-10, -10}, {-5, -5},
                                     [&](const glm::dvec3& lo, const glm::dvec3&) { return lo.x <= x_max; },
                                     outside, crossing);
  EXPECT_GT(culled, clusters.cluster_count() / 4);  // Z order keeps clusters compact (22 of 64 here)
  EXPECT_TRUE(crossing.first.empty());
  const auto boxes = triangle_boxes(mesh);
  const auto c = classes(outside, crossing, boxes.size());
  for (size_t t = 0; t < boxes.size(); ++t) {
    if (boxes[t].hi.x <= 64) {
      EXPECT_EQ(c[t], 0) << "visible triangle " << t << " culled";
    }
  }
  // Contiguous clusters become one run: far fewer runs than clusters drawn.
  EXPECT_LT(outside.first.size(), size_t(clusters.cluster_count() - culled));
}

}  // namespace
