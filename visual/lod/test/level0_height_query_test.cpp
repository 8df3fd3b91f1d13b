// Level0 height query: a hinted query (the walls walk Level1's perimeter
// with the last triangle as a hint) gives bit for bit the height of the
// plain bucket scan, whatever the hint, also on edges and vertices.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "lod/level0_height_query.h"
#include "lod/roam_level0_mesh.h"
#include "lod_test_terrain.h"

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(Level0HeightQuery, HintedWalksGiveTheScansHeightsBitForBit) {
  const auto hf = lod_checks::synthetic(257, 11);
  const auto level0 = ig::lod::build_level0_mesh(hf, {2048});
  const ig::lod::Level0HeightQuery query(level0, hf.width, hf.height);
  int checked = 0, hint = -1;
  // Rows, columns and a diagonal of whole samples: points on vertices and
  // on the axis-aligned and diagonal edges of the bintree triangles.
  for (int j = 0; j < hf.height; j += 17)
    for (int i = 0; i < hf.width; ++i, ++checked)
      ASSERT_TRUE(same_bits(query.height_at(i, j, &hint), query.height_at(i, j))) << i << ", " << j;
  for (int i = 3; i < hf.width; i += 31)
    for (int j = hf.height - 1; j >= 0; --j, ++checked)
      ASSERT_TRUE(same_bits(query.height_at(i, j, &hint), query.height_at(i, j))) << i << ", " << j;
  for (int k = 0; k < hf.width; ++k, ++checked)
    ASSERT_TRUE(same_bits(query.height_at(k, k, &hint), query.height_at(k, k))) << k;
  // Any triangle as the hint, at points between samples too.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> at(0.0, hf.width - 1.0);
  std::uniform_int_distribution<int> triangle(0, int(level0.indices.size() / 3) - 1);
  for (int n = 0; n < 20000; ++n, ++checked) {
    const double i = n % 2 ? at(rng) : std::round(at(rng)), j = at(rng);
    int any = triangle(rng);
    ASSERT_TRUE(same_bits(query.height_at(i, j, &any), query.height_at(i, j))) << i << ", " << j;
  }
  EXPECT_GT(checked, 25000);
}

TEST(Level0HeightQuery, TheHintBecomesTheTriangleHoldingThePoint) {
  const auto hf = lod_checks::synthetic(129, 2);
  const auto level0 = ig::lod::build_level0_mesh(hf, {512});
  const ig::lod::Level0HeightQuery query(level0, hf.width, hf.height);
  int hint = -1;
  query.height_at(40.3, 70.6, &hint);
  ASSERT_GE(hint, 0);
  // The point lies in the hinted triangle's bounds.
  double lo_i = 1e30, hi_i = -1e30, lo_j = 1e30, hi_j = -1e30;
  for (int k = 0; k < 3; ++k) {
    const auto s = level0.samples[level0.indices[size_t(hint) * 3 + k]];
    lo_i = std::min(lo_i, double(s.x));
    hi_i = std::max(hi_i, double(s.x));
    lo_j = std::min(lo_j, double(s.y));
    hi_j = std::max(hi_j, double(s.y));
  }
  EXPECT_TRUE(40.3 >= lo_i && 40.3 <= hi_i && 70.6 >= lo_j && 70.6 <= hi_j);
}

}  // namespace
