// Level0 static ROAM mesh: crack-freedom, coverage, error behaviour, budgets,
// non-(2^n+1) DEMs, determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "lod/roam_level0_mesh.h"

namespace {

using ig::lod::build_level0_mesh;
using ig::lod::Level0Mesh;
using ig::lod::Level0Options;
using ig::terrain::Heightfield;

Heightfield make_hf(int w, int h, const std::function<float(int, int)>& f, double sx = 1.0, double sy = 1.0) {
  Heightfield hf;
  hf.width = w;
  hf.height = h;
  hf.spacing_x_m = sx;
  hf.spacing_y_m = sy;
  hf.heights.resize(std::size_t(w) * h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) hf.ref(i, j) = f(i, j);
  hf.finalize_stats();
  return hf;
}

// Deterministic fractal-ish terrain: a few octaves of value noise on a lattice.
Heightfield fractal(int w, int h, unsigned seed, double sx = 1.0, double sy = 1.0) {
  std::mt19937 rng(seed);
  const int lat = 65;
  std::vector<float> noise(lat * lat);
  for (auto& v : noise) v = float(rng() % 10000) / 10000.0f;
  auto value = [&](double x, double y) {
    const int xi = int(std::floor(x)), yi = int(std::floor(y));
    const double fx = x - xi, fy = y - yi;
    auto n = [&](int a, int b) { return noise[((b % lat + lat) % lat) * lat + ((a % lat + lat) % lat)]; };
    return (n(xi, yi) * (1 - fx) + n(xi + 1, yi) * fx) * (1 - fy) + (n(xi, yi + 1) * (1 - fx) + n(xi + 1, yi + 1) * fx) * fy;
  };
  return make_hf(
      w, h,
      [&](int i, int j) {
        double z = 0, amp = 200, freq = 1.0 / 32;
        for (int o = 0; o < 5; ++o, amp *= 0.5, freq *= 2) z += amp * value(i * freq + o * 7.1, j * freq + o * 3.3);
        return float(z + 1000.0);
      },
      sx, sy);
}

std::int64_t cross(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
  return std::int64_t(b.x - a.x) * (c.y - a.y) - std::int64_t(b.y - a.y) * (c.x - a.x);
}

// Checks everything structural about a mesh over hf. Returns false (and adds
// gtest failures) on the first class of problem found.
void check_mesh(const Level0Mesh& m, const Heightfield& hf) {
  ASSERT_EQ(m.indices.size() % 3, 0u);
  ASSERT_EQ(m.triangle_count, int(m.indices.size() / 3));
  ASSERT_EQ(m.positions.size(), m.samples.size());
  const int wm = hf.width - 1, hm = hf.height - 1;
  // Vertices: on DEM samples, positions consistent, no duplicates.
  std::map<std::pair<int, int>, int> seen;
  for (std::size_t v = 0; v < m.samples.size(); ++v) {
    const auto s = m.samples[v];
    ASSERT_TRUE(s.x >= 0 && s.x <= wm && s.y >= 0 && s.y <= hm) << s.x << "," << s.y;
    EXPECT_FLOAT_EQ(m.positions[v].x, float(s.x * hf.spacing_x_m));
    EXPECT_FLOAT_EQ(m.positions[v].y, float(s.y * hf.spacing_y_m));
    EXPECT_EQ(m.positions[v].z, hf.at(s.x, s.y));
    ASSERT_TRUE(seen.emplace(std::make_pair(s.x, s.y), int(v)).second) << "duplicate vertex";
  }
  // Triangles: CCW, non-degenerate; area sums to the footprint.
  std::int64_t area2 = 0;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const std::uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
    ASSERT_LT(std::max({a, b, c}), m.samples.size());
    const std::int64_t cr = cross(m.samples[a], m.samples[b], m.samples[c]);
    ASSERT_GT(cr, 0) << "triangle " << t / 3 << " not CCW / degenerate";
    area2 += cr;
    for (auto [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) ++edges[{std::min(p, q), std::max(p, q)}];
  }
  EXPECT_EQ(area2, 2LL * wm * hm) << "footprint area";
  // Each edge: 2 triangles, or 1 when on the footprint boundary.
  for (const auto& [e, n] : edges) {
    const auto p = m.samples[e.first], q = m.samples[e.second];
    const bool boundary = (p.x == 0 && q.x == 0) || (p.x == wm && q.x == wm) || (p.y == 0 && q.y == 0) ||
                          (p.y == hm && q.y == hm);
    if (boundary) EXPECT_EQ(n, 1) << "boundary edge (" << p.x << "," << p.y << ")-(" << q.x << "," << q.y << ")";
    else EXPECT_EQ(n, 2) << "interior edge (" << p.x << "," << p.y << ")-(" << q.x << "," << q.y << ")";
  }
  // No T-junctions: no vertex strictly inside any edge.
  for (const auto& [e, n] : edges) {
    const auto p = m.samples[e.first], q = m.samples[e.second];
    for (const auto& s : m.samples) {
      if (s == p || s == q || cross(p, q, s) != 0) continue;
      const std::int64_t dot = std::int64_t(s.x - p.x) * (q.x - p.x) + std::int64_t(s.y - p.y) * (q.y - p.y);
      const std::int64_t len2 = std::int64_t(q.x - p.x) * (q.x - p.x) + std::int64_t(q.y - p.y) * (q.y - p.y);
      ASSERT_FALSE(dot > 0 && dot < len2) << "T-junction: vertex (" << s.x << "," << s.y << ") on edge";
    }
  }
}

// Max over DEM samples of |mesh height - DEM height| (interpolating on the mesh).
double vertical_error(const Level0Mesh& m, const Heightfield& hf) {
  double worst = 0;
  for (int j = 0; j < hf.height; ++j)
    for (int i = 0; i < hf.width; ++i) {
      const glm::ivec2 s{i, j};
      bool found = false;
      for (std::size_t t = 0; t < m.indices.size() && !found; t += 3) {
        const auto a = m.samples[m.indices[t]], b = m.samples[m.indices[t + 1]], c = m.samples[m.indices[t + 2]];
        const std::int64_t w0 = cross(b, c, s), w1 = cross(c, a, s), w2 = cross(a, b, s);
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const double tot = double(w0 + w1 + w2);
        const double z = (w0 * double(hf.at(a.x, a.y)) + w1 * double(hf.at(b.x, b.y)) + w2 * double(hf.at(c.x, c.y))) / tot;
        worst = std::max(worst, std::fabs(z - hf.at(i, j)));
        found = true;
      }
      EXPECT_TRUE(found) << "sample " << i << "," << j << " not covered";
    }
  return worst;
}

// Reference diamond errors, from the bintree itself: recurse over triangles
// to find each diamond's local error and child diamonds (union over its two
// triangles), then error(d) = max(local(d), error(children)).
struct RefDiamonds {
  int n = 0;
  std::vector<float> local;
  std::vector<std::vector<int>> kids;
  std::vector<float> memo;
  void visit(const Heightfield& hf, glm::ivec2 a, glm::ivec2 l, glm::ivec2 r) {
    const glm::ivec2 s = l + r;
    if (s.x % 2 || s.y % 2) return;
    const glm::ivec2 m = s / 2;
    const int id = m.y * n + m.x;
    if (std::max(l.x, r.x) < hf.width && std::max(l.y, r.y) < hf.height)
      local[id] = std::fabs(hf.at(m.x, m.y) - 0.5f * (hf.at(l.x, l.y) + hf.at(r.x, r.y)));
    for (auto [p, q] : {std::pair{a, l}, std::pair{r, a}}) {
      const glm::ivec2 c = p + q;
      if (c.x % 2 == 0 && c.y % 2 == 0) kids[id].push_back((c.y / 2) * n + c.x / 2);
    }
    visit(hf, m, a, l);
    visit(hf, m, r, a);
  }
  float error(int id) {
    if (memo[id] >= 0) return memo[id];
    float e = local[id];
    for (int k : kids[id]) e = std::max(e, error(k));
    return memo[id] = e;
  }
};

TEST(RoamLevel0, ErrorGridMatchesRecursiveReference) {
  for (auto [w, h] : {std::pair{65, 65}, std::pair{33, 33}, std::pair{50, 21}}) {
    const Heightfield hf = fractal(w, h, 7);
    const auto g = ig::lod::compute_level0_errors(hf);
    const int n = g.side, s = n - 1;
    ASSERT_GE(n, std::max(w, h));
    RefDiamonds ref;
    ref.n = n;
    ref.local.assign(std::size_t(n) * n, 0.0f);
    ref.kids.resize(std::size_t(n) * n);
    ref.memo.assign(std::size_t(n) * n, -1.0f);
    ref.visit(hf, {s, 0}, {s, s}, {0, 0});
    ref.visit(hf, {0, s}, {0, 0}, {s, s});
    for (int k = 0; k < n * n; ++k)
      ASSERT_NEAR(g.error[k], ref.error(k), 2e-3f) << w << "x" << h << " at " << k % n << "," << k / n;
  }
}

TEST(RoamLevel0, CrackFreeOnSquareDems) {
  for (int n : {65, 129}) {
    const Heightfield hf = fractal(n, n, 11 + n);
    for (int budget : {2, 16, 100, 512, 1500}) {
      SCOPED_TRACE(testing::Message() << n << "x" << n << " budget " << budget);
      const Level0Mesh m = build_level0_mesh(hf, {budget, 0.0});
      check_mesh(m, hf);
      EXPECT_GE(m.triangle_count, std::min(budget, 2 * (n - 1) * (n - 1)));
    }
  }
}

TEST(RoamLevel0, CrackFreeOnNonPowerOfTwoDems) {
  for (auto [w, h] : {std::pair{100, 70}, std::pair{70, 100}, std::pair{61, 41}, std::pair{2, 2}, std::pair{3, 9},
                      std::pair{66, 66}}) {
    const Heightfield hf = fractal(w, h, 3, 30.0, 20.0);
    for (int budget : {2, 64, 400, 2000}) {
      SCOPED_TRACE(testing::Message() << w << "x" << h << " budget " << budget);
      const Level0Mesh m = build_level0_mesh(hf, {budget, 0.0});
      check_mesh(m, hf);
    }
  }
}

TEST(RoamLevel0, FullRefinementReproducesDem) {
  for (auto [w, h] : {std::pair{33, 33}, std::pair{40, 23}}) {
    const Heightfield hf = fractal(w, h, 5);
    const Level0Mesh m = build_level0_mesh(hf, {1 << 30, 0.0});
    check_mesh(m, hf);
    EXPECT_EQ(m.max_error_m, 0.0);
    EXPECT_EQ(vertical_error(m, hf), 0.0);
  }
}

TEST(RoamLevel0, PlaneGivesTwoTriangles) {
  for (auto [w, h] : {std::pair{129, 129}, std::pair{100, 70}}) {
    const Heightfield hf = make_hf(w, h, [](int i, int j) { return float(1234.5 + 0.37 * i - 1.91 * j); }, 90.0, 92.6);
    const Level0Mesh m = build_level0_mesh(hf);
    EXPECT_EQ(m.max_error_m, 0.0);
    if (w == h) {
      EXPECT_EQ(m.triangle_count, 2);
      EXPECT_EQ(m.positions.size(), 4u);
    } else {
      // The two root triangles, clipped to the DEM rectangle: still a few.
      check_mesh(m, hf);
      EXPECT_LE(m.triangle_count, 4);
    }
  }
}

TEST(RoamLevel0, ErrorFallsAsBudgetGrows) {
  const Heightfield hf = fractal(257, 257, 42);
  double prev_err = 1e30, prev_vert = 1e30, first_vert = 0;
  for (int budget : {64, 256, 1024, 4096}) {
    const Level0Mesh m = build_level0_mesh(hf, {budget, 0.0});
    const double vert = vertical_error(m, hf);
    std::printf("budget %5d: %5d triangles, max_error %.3f m, vertical error %.3f m\n", budget, m.triangle_count,
                m.max_error_m, vert);
    EXPECT_LE(m.max_error_m, prev_err);
    EXPECT_LE(vert, prev_vert * 1.05);  // allowed to wobble a little, trend must be down
    if (budget == 64) first_vert = vert;
    if (budget == 4096) {
      EXPECT_LT(vert, 0.5 * first_vert);
    }
    // Documented bound on this terrain: vertical error <= 3 x max_error_m.
    EXPECT_LE(vert, 3.0 * m.max_error_m + 1e-6);
    prev_err = m.max_error_m;
    prev_vert = vert;
  }
}

TEST(RoamLevel0, SpikeRefinesTowardTheSpike) {
  const int n = 129, si = 93, sj = 37;
  const Heightfield hf = make_hf(n, n, [&](int i, int j) { return (i == si && j == sj) ? 500.0f : 100.0f; });
  const Level0Mesh m = build_level0_mesh(hf, {256, 0.0});
  check_mesh(m, hf);
  // The spike itself is a vertex and the mesh's smallest triangles touch it.
  bool has_spike = false;
  for (const auto& s : m.samples) has_spike |= (s == glm::ivec2{si, sj});
  EXPECT_TRUE(has_spike);
  EXPECT_EQ(m.max_error_m, 0.0);
  std::int64_t min_area = INT64_MAX, max_area = 0;
  double min_dist = 1e9;
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const auto a = m.samples[m.indices[t]], b = m.samples[m.indices[t + 1]], c = m.samples[m.indices[t + 2]];
    const std::int64_t ar = cross(a, b, c);
    max_area = std::max(max_area, ar);
    if (ar < min_area) {
      min_area = ar;
      min_dist = 1e9;
    }
    if (ar == min_area) {
      const glm::dvec2 cen = (glm::dvec2(a) + glm::dvec2(b) + glm::dvec2(c)) / 3.0;
      min_dist = std::min(min_dist, std::hypot(cen.x - si, cen.y - sj));
    }
  }
  EXPECT_LT(min_dist, 3.0);
  EXPECT_GT(max_area, 64 * min_area);
  EXPECT_LE(m.triangle_count, 256);  // exact error 0 reached before the budget
}

TEST(RoamLevel0, BudgetRespectedWithSmallOvershoot) {
  const Heightfield sq = fractal(257, 257, 9);
  for (int budget : {2, 10, 100, 2048, 5000}) {
    const Level0Mesh m = build_level0_mesh(sq, {budget, 0.0});
    EXPECT_GE(m.triangle_count, budget);
    // One split adds at most 2 per tree level of forced splits: 4*log2(N)+2.
    EXPECT_LE(m.triangle_count, budget + 4 * 8 + 2) << budget;
  }
  const Heightfield odd = fractal(150, 90, 9);
  for (int budget : {10, 100, 2048}) {
    const Level0Mesh m = build_level0_mesh(odd, {budget, 0.0});
    // Clipping a border triangle can turn it into up to 3: documented 10 % + forced splits.
    EXPECT_LE(m.triangle_count, budget + budget / 10 + 4 * 8 + 2) << budget;
  }
}

TEST(RoamLevel0, ErrorTargetStopsRefinement) {
  const Heightfield hf = fractal(129, 129, 17);
  const Level0Mesh coarse = build_level0_mesh(hf, {1 << 30, 20.0});
  EXPECT_LE(coarse.max_error_m, 20.0);
  const Level0Mesh fine = build_level0_mesh(hf, {1 << 30, 2.0});
  EXPECT_LE(fine.max_error_m, 2.0);
  EXPECT_LT(coarse.triangle_count, fine.triangle_count);
  check_mesh(coarse, hf);
}

TEST(RoamLevel0, Deterministic) {
  const Heightfield hf = fractal(100, 70, 23);
  const Level0Mesh a = build_level0_mesh(hf, {700, 0.0}), b = build_level0_mesh(hf, {700, 0.0});
  EXPECT_EQ(a.indices, b.indices);
  EXPECT_EQ(a.samples, b.samples);
  EXPECT_EQ(a.max_error_m, b.max_error_m);
}

TEST(RoamLevel0, RejectsTinyGrids) {
  Heightfield hf = make_hf(1, 5, [](int, int) { return 0.0f; });
  EXPECT_THROW(build_level0_mesh(hf), std::invalid_argument);
}

}  // namespace
