// The chunk quadtree shared by chunked LOD and CDLOD (visual/lod/chunk_quadtree.*):
// depth for DEMs of any size, leaves tile the DEM once at full resolution,
// errors match a brute-force evaluation and never grow down the tree.

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "lod/chunk_grid_error.h"
#include "lod/chunk_quadtree.h"
#include "lod_test_terrain.h"

namespace {

using ig::lod::kChunkQuads;

ig::terrain::Heightfield bumpy(int w, int h) {
  return lod_checks::heightfield_from(w, h, 30.0, 30.0, [](int i, int j) {
    return 80.0 * std::sin(0.31 * i) * std::cos(0.17 * j) + 2.0 * ((i * 5 + j * 3) % 7);
  });
}

// Corners of a regular grid's triangles, for the brute-force check.
std::vector<glm::ivec2> grid_triangles(int quads, int stride) {
  std::vector<glm::ivec2> t;
  for (int j = 0; j < quads; ++j)
    for (int i = 0; i < quads; ++i) {
      const glm::ivec2 p(i * stride, j * stride);
      t.insert(t.end(), {p, p + glm::ivec2(stride, 0), p + glm::ivec2(stride), p, p + glm::ivec2(stride),
                         p + glm::ivec2(0, stride)});
    }
  return t;
}

TEST(ChunkQuadtree, DepthCoversTheDemForAnySize) {
  for (auto [w, h, depth] : {std::tuple{2, 2, 0}, std::tuple{33, 20, 0}, std::tuple{65, 65, 1},
                             std::tuple{1025, 1025, 5}, std::tuple{1201, 1201, 6}, std::tuple{34, 3, 1}}) {
    const auto hf = bumpy(w, h);
    const ig::lod::ChunkQuadtree tree(hf);
    EXPECT_EQ(tree.depth(), depth) << w << "x" << h;
    EXPECT_EQ(tree.node(0).stride, 1 << depth);
    // Leaves: full resolution, each DEM quad in exactly one leaf.
    std::vector<int> cover(size_t(w - 1) * (h - 1), 0);
    long long leaf_triangles = 0;
    for (const auto& n : tree.nodes()) {
      if (!n.leaf()) continue;
      EXPECT_EQ(n.stride, 1);
      leaf_triangles += n.triangles;
      for (int j = n.j0; j < std::min(n.j0 + kChunkQuads, h - 1); ++j)
        for (int i = n.i0; i < std::min(n.i0 + kChunkQuads, w - 1); ++i) ++cover[size_t(j) * (w - 1) + i];
    }
    for (int c : cover) ASSERT_EQ(c, 1) << w << "x" << h;
    EXPECT_EQ(leaf_triangles, 2LL * (w - 1) * (h - 1));
  }
}

TEST(ChunkQuadtree, ErrorsMatchBruteForceAndNeverGrowTowardsTheLeaves) {
  const auto hf = bumpy(150, 97);
  const ig::lod::ChunkQuadtree tree(hf);
  ASSERT_EQ(tree.depth(), 3);
  bool some_error = false;
  for (const auto& n : tree.nodes()) {
    const float brute = ig::lod::triangles_max_error(hf, n.i0, n.j0, grid_triangles(kChunkQuads, n.stride));
    EXPECT_FLOAT_EQ(n.own_error_m, brute) << "node at " << n.i0 << "," << n.j0 << " level " << n.level;
    EXPECT_GE(n.error_m, n.own_error_m);
    if (n.leaf()) {
      EXPECT_EQ(n.own_error_m, 0.0f);
    }
    for (int c : n.children)
      if (c >= 0) {
        EXPECT_GE(n.error_m, tree.node(c).error_m);
        EXPECT_EQ(tree.node(c).parent, &n - tree.nodes().data());
      }
    some_error |= n.own_error_m > 1.0f;
    // The box holds every sample of the node.
    glm::dvec3 lo, hi;
    tree.box(n, lo, hi);
    const auto r = ig::lod::sample_height_range(hf, n.i0, n.j0, n.size(), n.size());
    EXPECT_EQ(lo.z, r.min_m);
    EXPECT_EQ(hi.z, r.max_m);
    EXPECT_LE(hi.x, (hf.width - 1) * hf.spacing_x_m);
  }
  EXPECT_TRUE(some_error);
}

TEST(ChunkQuadtree, BoxDistances) {
  const glm::dvec3 lo(0, 0, 0), hi(10, 10, 5);
  EXPECT_EQ(ig::lod::box_distance({5, 5, 2}, lo, hi), 0.0);
  EXPECT_DOUBLE_EQ(ig::lod::box_distance({13, 14, 5}, lo, hi), 5.0);
  EXPECT_DOUBLE_EQ(ig::lod::box_far_distance({0, 0, 5}, lo, hi), std::sqrt(200.0 + 25.0));
}

}  // namespace
