// GeoMipMapping's CPU side (visual/lod/geomipmap_blocks.*): every stitched
// block configuration is a crack-free triangulation whose sides use exactly
// the stride the neighbour uses, neighbours agree on their shared side, the
// precomputed errors match a brute-force evaluation, and DEMs of any size
// are covered.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "lod/chunk_grid_error.h"
#include "lod/geomipmap_blocks.h"
#include "lod_test_terrain.h"
#include "terrain/synthetic_terrain.h"

namespace {

using ig::lod::GeoMipConfig;
using ig::lod::kGeoMipBlockQuads;
using ig::lod::kGeoMipLevels;
constexpr int N = kGeoMipBlockQuads;

// A non-square, non-2^n+1 heightfield with sharp detail (so coarse levels err).
ig::terrain::Heightfield bumpy(int w, int h) {
  return lod_checks::heightfield_from(w, h, 30.0, 25.0, [](int i, int j) {
    return 100.0 * std::sin(0.37 * i) * std::cos(0.23 * j) + 3.0 * ((i * 7 + j * 13) % 11) + 0.5 * i;
  });
}

std::vector<GeoMipConfig> all_configs() {
  std::vector<GeoMipConfig> out;
  for (int l = 0; l < kGeoMipLevels; ++l)
    for (int s0 = l; s0 < kGeoMipLevels; ++s0)
      for (int s1 = l; s1 < kGeoMipLevels; ++s1)
        for (int s2 = l; s2 < kGeoMipLevels; ++s2)
          for (int s3 = l; s3 < kGeoMipLevels; ++s3) {
            GeoMipConfig c;
            c.level = l;
            c.side_level = {s0, s1, s2, s3};
            out.push_back(c);
          }
  return out;
}

// Which side a boundary segment lies on (-1: interior).
int side_of(glm::ivec2 a, glm::ivec2 b) {
  if (a.y == 0 && b.y == 0) return ig::lod::kSouth;
  if (a.x == N && b.x == N) return ig::lod::kEast;
  if (a.y == N && b.y == N) return ig::lod::kNorth;
  if (a.x == 0 && b.x == 0) return ig::lod::kWest;
  return -1;
}

TEST(GeoMipMapTriangles, EveryConfigurationIsACrackFreeTriangulationOfTheBlock) {
  const auto configs = all_configs();
  ASSERT_EQ(configs.size(), 2275u);  // sum over levels l of (6 - l)^4
  for (const GeoMipConfig& c : configs) {
    SCOPED_TRACE("level " + std::to_string(c.level) + " sides " + std::to_string(c.side_level[0]) +
                 std::to_string(c.side_level[1]) + std::to_string(c.side_level[2]) + std::to_string(c.side_level[3]));
    const auto t = ig::lod::geomipmap_triangles(c);
    ASSERT_EQ(t.size() % 3, 0u);
    long long area2 = 0;
    std::map<std::pair<int, int>, int> directed;  // (from, to) vertex ids -> count
    auto id = [](glm::ivec2 p) { return p.y * (N + 1) + p.x; };
    for (size_t k = 0; k < t.size(); k += 3) {
      const long long a2 = (long long)(t[k + 1].x - t[k].x) * (t[k + 2].y - t[k].y) -
                           (long long)(t[k + 1].y - t[k].y) * (t[k + 2].x - t[k].x);
      ASSERT_GT(a2, 0) << "every triangle counter-clockwise with non-zero area";
      area2 += a2;
      for (int e = 0; e < 3; ++e) ++directed[{id(t[k + e]), id(t[k + (e + 1) % 3])}];
    }
    EXPECT_EQ(area2, 2LL * N * N) << "the triangles tile the block exactly";
    // Interior edges are used once each way (a manifold: no overlaps, no
    // T-junctions); boundary edges once, and on each side the boundary
    // vertices are exactly the multiples of that side's stride.
    std::array<std::set<int>, 4> side_vertices;
    for (const auto& [e, n] : directed) {
      ASSERT_EQ(n, 1);
      const glm::ivec2 a(e.first % (N + 1), e.first / (N + 1)), b(e.second % (N + 1), e.second / (N + 1));
      const int side = side_of(a, b);
      if (side < 0) {
        ASSERT_EQ(directed.count({e.second, e.first}), 1u) << "interior edge without its twin";
        continue;
      }
      ASSERT_EQ(directed.count({e.second, e.first}), 0u);
      const bool horizontal = side == ig::lod::kSouth || side == ig::lod::kNorth;
      side_vertices[size_t(side)].insert(horizontal ? a.x : a.y);
      side_vertices[size_t(side)].insert(horizontal ? b.x : b.y);
    }
    for (int s = 0; s < 4; ++s) {
      std::set<int> expected;
      for (int v = 0; v <= N; v += 1 << c.side_level[size_t(s)]) expected.insert(v);
      EXPECT_EQ(side_vertices[size_t(s)], expected) << "side " << s;
    }
  }
}

TEST(GeoMipMapBlocks, NeighboursDrawTheirSharedSideAtTheSameStride) {
  const auto hf = bumpy(300, 170);
  const ig::lod::GeoMipMapBlocks blocks(hf);
  ASSERT_EQ(blocks.blocks_x(), 10);  // ceil(299 / 32)
  ASSERT_EQ(blocks.blocks_y(), 6);   // ceil(169 / 32)
  std::vector<int> levels(blocks.blocks().size());
  for (size_t k = 0; k < levels.size(); ++k) levels[k] = int((k * 7919) % kGeoMipLevels);
  for (int by = 0; by < blocks.blocks_y(); ++by)
    for (int bx = 0; bx < blocks.blocks_x(); ++bx) {
      const auto c = blocks.config_of(bx, by, levels);
      for (int s : c.side_level) EXPECT_GE(s, c.level);
      if (bx + 1 < blocks.blocks_x()) {
        EXPECT_EQ(c.side_level[ig::lod::kEast], blocks.config_of(bx + 1, by, levels).side_level[ig::lod::kWest]);
      }
      if (by + 1 < blocks.blocks_y()) {
        EXPECT_EQ(c.side_level[ig::lod::kNorth], blocks.config_of(bx, by + 1, levels).side_level[ig::lod::kSouth]);
      }
    }
}

TEST(GeoMipMapBlocks, ErrorsMatchABruteForceEvaluationOfTheDrawnTriangles) {
  const auto hf = bumpy(101, 77);  // edge blocks are clamped (100 = 3 * 32 + 4)
  const ig::lod::GeoMipMapBlocks blocks(hf);
  bool some_coarse_error = false;
  for (int by = 0; by < blocks.blocks_y(); ++by)
    for (int bx = 0; bx < blocks.blocks_x(); ++bx) {
      const auto& b = blocks.block(bx, by);
      EXPECT_EQ(b.error[0], 0.0f) << "level 0 is full resolution";
      for (int l = 0; l < kGeoMipLevels; ++l) {
        GeoMipConfig c;
        c.level = l;
        c.side_level = {l, l, l, l};
        const auto tri = ig::lod::geomipmap_triangles(c);
        EXPECT_FLOAT_EQ(b.error[size_t(l)], ig::lod::triangles_max_error(hf, b.i0, b.j0, tri));
        EXPECT_EQ(b.triangles[size_t(l)], ig::lod::triangles_nondegenerate_count(hf, b.i0, b.j0, tri));
        some_coarse_error |= b.error[size_t(l)] > 1.0f;
      }
      // A stitched configuration: piece by piece, the level's plain error and
      // each strip's exact error; together they bound the whole block's.
      GeoMipConfig s;
      s.level = 1;
      s.side_level = {3, 1, 5, 2};
      const auto st = blocks.stats(bx, by, s);
      float pieces = b.error[1];
      for (int side = 0; side < 4; ++side) {
        const float e = blocks.strip_error(bx, by, s, side);
        EXPECT_FLOAT_EQ(e, ig::lod::triangles_max_error(hf, b.i0, b.j0, ig::lod::geomipmap_strip_triangles(s, side)));
        pieces = std::max(pieces, e);
      }
      EXPECT_EQ(blocks.strip_error(bx, by, s, ig::lod::kEast), 0.0f) << "not stitched";
      const auto all = ig::lod::geomipmap_triangles(s);
      EXPECT_EQ(st.error_m, pieces);
      EXPECT_GE(st.error_m, ig::lod::triangles_max_error(hf, b.i0, b.j0, all));
      EXPECT_EQ(st.triangles, ig::lod::triangles_nondegenerate_count(hf, b.i0, b.j0, all));
      EXPECT_EQ(blocks.stats(bx, by, s).error_m, st.error_m) << "cached alike";
    }
  EXPECT_TRUE(some_coarse_error);
  // The clamped east column of blocks covers only 4 quads: 8 triangles per row of level 0.
  EXPECT_EQ(blocks.block(3, 0).triangles[0], 2 * 4 * 32);
  EXPECT_EQ(blocks.block(3, 2).triangles[0], 2 * 4 * 12);  // 76 = 2 * 32 + 12
}

TEST(GeoMipMapBlocks, SelectionTakesTheCoarsestLevelWithinTolerance) {
  const std::array<float, kGeoMipLevels> err{0.0f, 1.0f, 2.0f, 8.0f, 4.0f, 50.0f};
  // rho = err / D * ppr; ppr 1000, D 1000 m: rho = err px.
  EXPECT_EQ(ig::lod::geomipmap_select_level(err, 1000.0, 0.5, 1000.0, 100.0), 5);
  EXPECT_EQ(ig::lod::geomipmap_select_level(err, 1000.0, 0.5, 1000.0, 10.0), 4);  // coarsest, not first
  EXPECT_EQ(ig::lod::geomipmap_select_level(err, 1000.0, 0.5, 1000.0, 3.0), 2);
  EXPECT_EQ(ig::lod::geomipmap_select_level(err, 1000.0, 0.5, 1000.0, 0.5), 0);
  EXPECT_EQ(ig::lod::geomipmap_select_level(err, 0.0, 0.5, 1000.0, 1.0), 0);  // eye inside the box
  int previous = kGeoMipLevels;
  for (double tau : {64.0, 16.0, 4.0, 1.0, 0.25}) {
    const int l = ig::lod::geomipmap_select_level(err, 1000.0, 0.5, 1000.0, tau);
    EXPECT_LE(l, previous) << "a smaller tolerance never picks a coarser level";
    previous = l;
  }
}

TEST(GeoMipMapBlocks, AnySizeDemIsCovered) {
  for (auto [w, h] : {std::pair{2, 2}, std::pair{3, 40}, std::pair{65, 65}, std::pair{1201, 37}}) {
    const auto hf = bumpy(w, h);
    const ig::lod::GeoMipMapBlocks blocks(hf);
    long long tri = 0;
    for (const auto& b : blocks.blocks()) tri += b.triangles[0];
    EXPECT_EQ(tri, 2LL * (w - 1) * (h - 1)) << w << "x" << h << ": level 0 is every DEM quad once";
  }
}

}  // namespace
