// CDLOD's CPU side (visual/lod/cdlod_selection.*): the selection tiles the
// DEM once, LODs respect their ranges, and the morphed vertices
// (cdlod_vertex, the CPU mirror of shaders/cdlod.vert) of neighbouring
// pieces coincide along every shared edge, whatever their LODs: no cracks.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>
#include <vector>

#include "lod/cdlod_selection.h"
#include "lod/chunk_quadtree.h"
#include "lod_test_terrain.h"

namespace {

using ig::lod::CdlodArea;
using ig::lod::CdlodRanges;
using ig::lod::ChunkQuadtree;
using ig::lod::kChunkQuads;

ig::terrain::Heightfield bumpy(int w, int h) {
  return lod_checks::heightfield_from(w, h, 30.0, 30.0, [](int i, int j) {
    return 300.0 + 200.0 * std::sin(0.05 * i) * std::cos(0.04 * j) + 20.0 * std::sin(0.9 * i + 0.4 * j);
  });
}

const ig::lod::BoxVisible kAll = [](const glm::dvec3&, const glm::dvec3&) { return true; };

// The piece's region in samples [x0, x1] x [y0, y1] (before clamping) and stride.
struct Piece {
  int x0, y0, x1, y1, stride, lod;
};
Piece piece_of(const ChunkQuadtree& tree, const CdlodArea& a) {
  const auto& n = tree.node(a.node);
  Piece p{n.i0, n.j0, n.i0 + n.size(), n.j0 + n.size(), n.stride, a.lod};
  if (a.quadrant >= 0) {
    const int half = n.size() / 2;
    p.x0 += (a.quadrant & 1) * half;
    p.y0 += (a.quadrant >> 1) * half;
    p.x1 = p.x0 + half;
    p.y1 = p.y0 + half;
  }
  return p;
}

struct Case {
  int w, h;
  double lod0_range_m;
  glm::dvec3 eye;
};

std::vector<Case> cases() {
  return {{257, 257, 200.0, {3000, 3000, 700}},   {257, 257, 120.0, {10, 10, 600}},
          {257, 257, 400.0, {7600, 100, 2000}},   {201, 150, 150.0, {2500, 4000, 900}},
          {300, 300, 600.0, {-2000, 4500, 1500}}, {257, 257, 2000.0, {4000, 4000, 3500}},
          {129, 300, 50.0, {1900, 20, 420}}};
}

// A case's terrain, its chunk quadtree (which refers to the terrain) and
// CDLOD's selection from its eye.
struct Selection {
  ig::terrain::Heightfield hf;
  ChunkQuadtree tree;
  CdlodRanges r;
  std::vector<CdlodArea> areas;
  explicit Selection(const Case& c) : hf(bumpy(c.w, c.h)), tree(hf) {
    r.lod0_range_m = c.lod0_range_m;
    r.top_lod = tree.depth();
    areas = ig::lod::cdlod_select(tree, r, c.eye, kAll);
  }
  Selection(const Selection&) = delete;
  Selection& operator=(const Selection&) = delete;
};

TEST(CdlodSelection, PiecesTileTheDemOnceAndRespectTheirRanges) {
  for (const Case& c : cases()) {
    const Selection sel(c);
    const auto& tree = sel.tree;
    const auto& r = sel.r;
    const auto& areas = sel.areas;
    ASSERT_FALSE(areas.empty());
    std::vector<int> cover(size_t(c.w - 1) * (c.h - 1), 0);
    std::set<int> lods;
    for (const CdlodArea& a : areas) {
      const Piece p = piece_of(tree, a);
      EXPECT_EQ(p.stride, 1 << a.lod);
      lods.insert(a.lod);
      for (int j = p.y0; j < std::min(p.y1, c.h - 1); ++j)
        for (int i = p.x0; i < std::min(p.x1, c.w - 1); ++i) ++cover[size_t(j) * (c.w - 1) + i];
      // Every point drawn at LOD k lies beyond range(k - 1).
      glm::dvec3 lo, hi;
      if (a.quadrant < 0)
        tree.box(tree.node(a.node), lo, hi);
      else
        tree.quadrant_box(tree.node(a.node), a.quadrant, lo, hi);
      if (a.lod > 0) {
        EXPECT_GT(ig::lod::box_distance(c.eye, lo, hi), r.range(a.lod - 1));
      }
    }
    for (int k : cover) ASSERT_EQ(k, 1);
    EXPECT_GE(lods.size(), 2u) << "the cases are chosen to mix LODs; eye " << c.eye.x << "," << c.eye.y << "," << c.eye.z;
  }
}

// Along every shared edge between two pieces, the final (morphed) positions
// of the vertices each piece puts there are the same set: the two edges are
// the same polyline.
TEST(CdlodSelection, MorphedEdgesOfNeighbouringPiecesCoincide) {
  int shared_edges = 0, mixed_lod_edges = 0, morphing_vertices = 0;
  for (const Case& c : cases()) {
    const Selection sel(c);
    const auto& hf = sel.hf;
    const auto& tree = sel.tree;
    const auto& r = sel.r;
    const auto& areas = sel.areas;
    std::vector<Piece> pieces;
    for (const auto& a : areas) pieces.push_back(piece_of(tree, a));
    // Clamp to the DEM: shared edges are compared where both pieces are on it.
    const int xmax = c.w - 1, ymax = c.h - 1;
    auto vertices_on = [&](const Piece& p, bool vertical, int line, int from, int to) {
      std::vector<std::tuple<double, double, double>> out;
      const int first = vertical ? p.y0 : p.x0;
      for (int t = first; t <= (vertical ? p.y1 : p.x1); t += p.stride) {
        if (t < from || t > to) continue;
        const glm::ivec2 s = vertical ? glm::ivec2(line, t) : glm::ivec2(t, line);
        const glm::dvec3 v = ig::lod::cdlod_vertex(hf, r, s, p.lod, c.eye);
        const glm::dvec3 unmorphed(std::min(s.x, xmax), std::min(s.y, ymax), 0.0);
        if (std::abs(v.x - unmorphed.x) + std::abs(v.y - unmorphed.y) > 0.0 &&
            std::abs(v.x - std::round(v.x)) + std::abs(v.y - std::round(v.y)) > 1e-9)
          ++morphing_vertices;
        out.emplace_back(std::round(v.x * 1e6), std::round(v.y * 1e6), std::round(v.z * 1e6));
      }
      std::sort(out.begin(), out.end());
      out.erase(std::unique(out.begin(), out.end()), out.end());
      return out;
    };
    for (size_t a = 0; a < pieces.size(); ++a)
      for (size_t b = 0; b < pieces.size(); ++b) {
        if (a == b) continue;
        const Piece &A = pieces[a], &B = pieces[b];
        // A's east side on B's west side, or A's north side on B's south side.
        for (int vertical = 0; vertical < 2; ++vertical) {
          const bool v = vertical == 1;
          if (v ? A.x1 != B.x0 : A.y1 != B.y0) continue;
          if ((v ? A.x1 : A.y1) > (v ? xmax : ymax)) continue;  // past the DEM: folded, no neighbour
          const int from = std::max(v ? A.y0 : A.x0, v ? B.y0 : B.x0);
          const int to = std::min({v ? A.y1 : A.x1, v ? B.y1 : B.x1, v ? ymax : xmax});
          if (from >= to) continue;
          const int line = v ? A.x1 : A.y1;
          ++shared_edges;
          mixed_lod_edges += A.lod != B.lod;
          EXPECT_EQ(vertices_on(A, v, line, from, to), vertices_on(B, v, line, from, to))
              << "pieces at LOD " << A.lod << " and " << B.lod << " on line " << line << " [" << from << ", " << to
              << "]";
        }
      }
  }
  EXPECT_GT(shared_edges, 50);
  EXPECT_GT(mixed_lod_edges, 10) << "the check must see edges between different LODs";
  EXPECT_GT(morphing_vertices, 0) << "and vertices caught mid-morph";
}

TEST(CdlodSelection, VerticesAreExactBeforeTheMorphAndCoarseAfterIt) {
  const auto hf = bumpy(257, 257);
  const ChunkQuadtree tree(hf);
  CdlodRanges r;
  r.lod0_range_m = 100.0;
  r.top_lod = tree.depth();
  const glm::ivec2 odd(41, 40);  // odd on the LOD 0 grid along x
  const glm::dvec3 at(41 * 30.0, 40 * 30.0, hf.at(41, 40));
  // Near: the sample itself.
  glm::dvec3 v = ig::lod::cdlod_vertex(hf, r, odd, 0, at + glm::dvec3(0, 0, 10));
  EXPECT_EQ(v, glm::dvec3(41, 40, hf.at(41, 40)));
  // Beyond LOD 0's morph end (99 m) but before LOD 1's morph start: on the even neighbour.
  v = ig::lod::cdlod_vertex(hf, r, odd, 0, at + glm::dvec3(0, 0, 120));
  EXPECT_EQ(v, glm::dvec3(40, 40, hf.at(40, 40)));
  // Mid-morph: on the fine mesh's edge between the two samples.
  const double d = 0.5 * (r.morph_start(0) + r.morph_end(0));
  v = ig::lod::cdlod_vertex(hf, r, odd, 0, at + glm::dvec3(0, 0, d));
  EXPECT_GT(v.x, 40.0);
  EXPECT_LT(v.x, 41.0);
  EXPECT_NEAR(v.z, hf.at(41, 40) + (v.x - 41.0) * (hf.at(41, 40) - hf.at(40, 40)), 1e-3);
  // The top LOD never morphs.
  EXPECT_EQ(r.morph(r.top_lod, 1e9), 0.0);
  EXPECT_EQ(r.morph(0, 1e9), 1.0);
}

}  // namespace
