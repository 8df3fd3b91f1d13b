#include "lod/roam_level0_mesh.h"

#include "lod/bintree_split.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <queue>
#include <stdexcept>
#include <unordered_map>

namespace ig::lod {
namespace {

int enclosing_side(int w, int h) {
  int s = 1;
  while (s + 1 < std::max(w, h)) s *= 2;
  return s + 1;
}

// Errors below this (relative to the largest |height|) are float round-off:
// a tilted plane stored as float must still come out as exactly 2 triangles.
float flush_epsilon(const terrain::Heightfield& hf) {
  float m = 0.0f;
  for (float v : hf.heights) m = std::max(m, std::fabs(v));
  return std::max(m, 1.0f) * std::ldexp(1.0f, -20);
}

// One bintree triangle. Vertex order (apex, left, right) is CCW seen from
// above; the hypotenuse ("base") runs left -> right. Edges: base = left-right,
// left edge = apex-left, right edge = right-apex.
struct Tri {
  glm::ivec2 v[3];
  int base = -1, left = -1, right = -1;  // neighbours across the base, the left and right edges
  int child = -1;  // first of two consecutive children: (m, apex, left), (m, right, apex)
  float whole_error = -1.0f;  // whole-triangle error, once measured (Level0Options::whole_triangle_error)
};

class Builder {
 public:
  Builder(const terrain::Heightfield& hf, const Level0ErrorGrid& eg, const Level0Options& o)
      : hf_(hf), eg_(eg), opts_(o), lim_x_(hf.width - 1), lim_y_(hf.height - 1) {}

  void run() {
    const int s = eg_.side - 1;
    // Root square split along its main diagonal (0,0)-(s,s).
    tris_.push_back(Tri{{{s, 0}, {s, s}, {0, 0}}});
    tris_.push_back(Tri{{{0, s}, {0, 0}, {s, s}}});
    tris_[0].base = 1;
    tris_[1].base = 0;
    leaves_in_ = 2;
    consider(0);
    consider(1);
    const double target = std::max(0.0, opts_.error_target_m);
    while (!queue_.empty() && leaves_in_ < opts_.triangle_budget) {
      const auto [err, id] = queue_.top();
      if (err <= target) break;
      queue_.pop();
      if (tris_[id].child >= 0) continue;  // already split by a forced split
      split(id);
    }
  }

  const std::vector<Tri>& tris() const { return tris_; }
  bool inside(const Tri& t) const {
    const int minx = std::min({t.v[0].x, t.v[1].x, t.v[2].x});
    const int miny = std::min({t.v[0].y, t.v[1].y, t.v[2].y});
    return minx < lim_x_ && miny < lim_y_;
  }
  static bool splittable(const Tri& t) {
    const glm::ivec2 s = t.v[1] + t.v[2];
    return (s.x % 2 == 0) && (s.y % 2 == 0);
  }
  float error_of(const Tri& t) const {
    const glm::ivec2 m = (t.v[1] + t.v[2]) / 2;
    float e = opts_.whole_triangle_error ? t.whole_error : eg_.error[static_cast<std::size_t>(m.y) * eg_.side + m.x];
    if (opts_.earth_radius_m > 0.0) {
      const glm::dvec2 d = glm::dvec2(t.v[1] - t.v[2]) * glm::dvec2(hf_.spacing_x_m, hf_.spacing_y_m);
      e += float((d.x * d.x + d.y * d.y) / (8.0 * opts_.earth_radius_m));
    }
    return e;
  }

 private:
  struct Entry {
    float err;
    int id;
    bool operator<(const Entry& o) const {  // max-heap on err, then lower id first
      return err < o.err || (err == o.err && id > o.id);
    }
  };

  // Largest |sample - plane| over the DEM samples inside t (edges included).
  float whole_error(const Tri& t) const {
    const glm::ivec2 a = t.v[0], b = t.v[1], c = t.v[2];
    const double ha = hf_.at_clamped(a.x, a.y), hb = hf_.at_clamped(b.x, b.y), hc = hf_.at_clamped(c.x, c.y);
    const double det = double(b.x - a.x) * (c.y - a.y) - double(c.x - a.x) * (b.y - a.y);
    if (det == 0.0) return 0.0f;
    // Plane h(i, j) = ha + gx (i - a.x) + gy (j - a.y).
    const double gx = ((hb - ha) * (c.y - a.y) - (hc - ha) * (b.y - a.y)) / det;
    const double gy = ((hc - ha) * (b.x - a.x) - (hb - ha) * (c.x - a.x)) / det;
    const int x0 = std::max(0, std::min({a.x, b.x, c.x})), x1 = std::min(lim_x_, std::max({a.x, b.x, c.x}));
    const int y0 = std::max(0, std::min({a.y, b.y, c.y})), y1 = std::min(lim_y_, std::max({a.y, b.y, c.y}));
    auto edge = [](glm::ivec2 p, glm::ivec2 q, int i, int j) {
      return std::int64_t(q.x - p.x) * (j - p.y) - std::int64_t(q.y - p.y) * (i - p.x);
    };
    const bool ccw = det > 0;
    float worst = 0.0f;
    for (int j = y0; j <= y1; ++j) {
      const float* row = hf_.heights.data() + std::size_t(j) * hf_.width;
      for (int i = x0; i <= x1; ++i) {
        const std::int64_t e0 = edge(a, b, i, j), e1 = edge(b, c, i, j), e2 = edge(c, a, i, j);
        const bool in = ccw ? (e0 >= 0 && e1 >= 0 && e2 >= 0) : (e0 <= 0 && e1 <= 0 && e2 <= 0);
        if (!in) continue;
        const double plane = ha + gx * (i - a.x) + gy * (j - a.y);
        worst = std::max(worst, float(std::abs(row[i] - plane)));
      }
    }
    return worst;
  }

  void consider(int id) {
    if (opts_.whole_triangle_error && tris_[id].whole_error < 0.0f && inside(tris_[id]) && splittable(tris_[id]))
      tris_[id].whole_error = whole_error(tris_[id]);
    const Tri& t = tris_[id];
    if (!inside(t) || !splittable(t)) return;
    const float e = error_of(t);
    if (e > 0.0f) queue_.push({e, id});
  }

  // A diamond split (lod/bintree_split.h) that keeps the count of leaves
  // inside the DEM and queues the new triangles by their error.
  void split(int x) {
    bintree::split(
        tris_, x, false, [](bool) {},
        [this](int p, int c0) {
          if (inside(tris_[p])) leaves_in_ += (inside(tris_[c0]) ? 1 : 0) + (inside(tris_[c0 + 1]) ? 1 : 0) - 1;
        },
        [this](int a, int b) {
          if (b >= 0) {
            consider(tris_[b].child);
            consider(tris_[b].child + 1);
          }
          consider(tris_[a].child);
          consider(tris_[a].child + 1);
        });
  }

  const terrain::Heightfield& hf_;
  const Level0ErrorGrid& eg_;
  Level0Options opts_;
  int lim_x_, lim_y_;
  std::vector<Tri> tris_;
  std::priority_queue<Entry> queue_;
  long long leaves_in_ = 0;
};

// Clips a CCW polygon of integer points to coordinate axis `ax` <= lim. All
// tree edges are axis-aligned or at 45 degrees, so the cut points are integer.
std::vector<glm::ivec2> clip_le(const std::vector<glm::ivec2>& in, int ax, int lim) {
  std::vector<glm::ivec2> out;
  const std::size_t n = in.size();
  for (std::size_t k = 0; k < n; ++k) {
    const glm::ivec2 p = in[k], q = in[(k + 1) % n];
    const bool pin = p[ax] <= lim, qin = q[ax] <= lim;
    if (pin) out.push_back(p);
    if (pin != qin && p[ax] != lim && q[ax] != lim) {
      const int d = q[ax] - p[ax];
      const int o = 1 - ax;
      glm::ivec2 c;
      c[ax] = lim;
      c[o] = p[o] + (q[o] - p[o]) * (lim - p[ax]) / d;  // exact: |dq[o]| is 0 or |d|
      out.push_back(c);
    }
  }
  // Remove consecutive duplicates (including wrap-around).
  std::vector<glm::ivec2> res;
  for (const auto& p : out)
    if (res.empty() || res.back() != p) res.push_back(p);
  while (res.size() > 1 && res.front() == res.back()) res.pop_back();
  return res;
}

}  // namespace

Level0ErrorGrid compute_level0_errors(const terrain::Heightfield& hf) {
  const int w = hf.width, hgt = hf.height;
  if (w < 2 || hgt < 2 || hf.heights.size() != std::size_t(w) * std::size_t(hgt))
    throw std::invalid_argument("build_level0_mesh: heightfield must be at least 2x2 with width*height samples");
  Level0ErrorGrid g;
  const int n = enclosing_side(w, hgt);
  const int s = n - 1;
  g.side = n;
  g.error.assign(std::size_t(n) * n, 0.0f);
  float* e = g.error.data();
  const float* hv = hf.heights.data();
  const float eps = flush_epsilon(hf);
  const int wm = w - 1, hm = hgt - 1;
  auto H = [&](int i, int j) { return hv[std::size_t(j) * w + i]; };
  auto E = [&](int i, int j) -> float& { return e[std::size_t(j) * n + i]; };
  // Local error of the diamond with hypotenuse (ia,ja)-(ib,jb) and midpoint
  // (i,j). Diamonds whose hypotenuse reaches outside the DEM carry no local
  // error (only their descendants'): no height outside the DEM is ever read.
  auto local = [&](int i, int j, int ia, int ja, int ib, int jb) {
    if (std::max(ia, ib) > wm || std::max(ja, jb) > hm) return 0.0f;
    const float d = std::fabs(H(i, j) - 0.5f * (H(ia, ja) + H(ib, jb)));
    return d <= eps ? 0.0f : d;
  };

  for (int h = 1; h <= s / 2; h *= 2) {
    const int h2 = 2 * h, q = h / 2;
    // Axis-aligned hypotenuses of length 2h. Children (h >= 2): the square
    // diamonds of side h centred at (i +- h/2, j +- h/2).
    for (int j = 0; j <= s; j += h2) {  // horizontal: i = h mod 2h, j = 0 mod 2h
      const bool fast = j <= hm;  // row inside the DEM
      for (int i = h; i < s; i += h2) {
        float v;
        if (fast && i + h <= wm) {
          const float* r = hv + std::size_t(j) * w;
          v = std::fabs(r[i] - 0.5f * (r[i - h] + r[i + h]));
          if (v <= eps) v = 0.0f;
        } else {
          v = local(i, j, i - h, j, i + h, j);
        }
        if (q > 0) {
          if (j - q >= 0) v = std::max({v, E(i - q, j - q), E(i + q, j - q)});
          if (j + q <= s) v = std::max({v, E(i - q, j + q), E(i + q, j + q)});
        }
        E(i, j) = v;
      }
    }
    for (int j = h; j < s; j += h2) {  // vertical: i = 0 mod 2h, j = h mod 2h
      for (int i = 0; i <= s; i += h2) {
        float v;
        if (j + h <= hm && i <= wm) {
          v = std::fabs(hv[std::size_t(j) * w + i] -
                        0.5f * (hv[std::size_t(j - h) * w + i] + hv[std::size_t(j + h) * w + i]));
          if (v <= eps) v = 0.0f;
        } else {
          v = local(i, j, i, j - h, i, j + h);
        }
        if (q > 0) {
          if (i - q >= 0) v = std::max({v, E(i - q, j - q), E(i - q, j + q)});
          if (i + q <= s) v = std::max({v, E(i + q, j - q), E(i + q, j + q)});
        }
        E(i, j) = v;
      }
    }
    // Square diamonds of side 2h centred at (i, j) = (h, h) mod 2h. The
    // hypotenuse is the main diagonal when the square's block index parity
    // ((i-h)/2h + (j-h)/2h) is even (the root square uses the main diagonal).
    // Children: the axis diamonds at the square's edge midpoints.
    for (int j = h; j < s; j += h2) {
      const int bj = (j - h) / h2;
      for (int i = h; i < s; i += h2) {
        const int bi = (i - h) / h2;
        float v;
        if (((bi + bj) & 1) == 0) v = local(i, j, i - h, j - h, i + h, j + h);
        else v = local(i, j, i - h, j + h, i + h, j - h);
        v = std::max({v, E(i - h, j), E(i + h, j), E(i, j - h), E(i, j + h)});
        E(i, j) = v;
      }
    }
  }
  return g;
}

Level0Mesh build_level0_mesh(const terrain::Heightfield& hf, const Level0Options& opts) {
  const auto t0 = std::chrono::steady_clock::now();
  const Level0ErrorGrid eg = compute_level0_errors(hf);
  Builder b(hf, eg, opts);
  b.run();

  Level0Mesh mesh;
  const int lim_x = hf.width - 1, lim_y = hf.height - 1;
  const bool clip = eg.side - 1 != lim_x || eg.side - 1 != lim_y;
  std::unordered_map<std::int64_t, std::uint32_t> vid;
  auto vertex = [&](glm::ivec2 p) {
    const std::int64_t key = std::int64_t(p.y) * eg.side + p.x;
    auto [it, fresh] = vid.try_emplace(key, std::uint32_t(mesh.positions.size()));
    if (fresh) {
      mesh.samples.push_back(p);
      mesh.positions.emplace_back(float(p.x * hf.spacing_x_m), float(p.y * hf.spacing_y_m), hf.at(p.x, p.y));
    }
    return it->second;
  };
  double max_err = 0.0;
  for (const Tri& t : b.tris()) {
    if (t.child >= 0 || !b.inside(t)) continue;
    if (Builder::splittable(t)) max_err = std::max(max_err, double(b.error_of(t)));
    if (!clip) {
      for (const auto& p : t.v) mesh.indices.push_back(vertex(p));
      continue;
    }
    std::vector<glm::ivec2> poly(t.v, t.v + 3);
    poly = clip_le(poly, 0, lim_x);
    if (poly.size() >= 3) poly = clip_le(poly, 1, lim_y);
    if (poly.size() < 3) continue;
    const std::uint32_t v0 = vertex(poly[0]);
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
      const glm::ivec2 a = poly[k] - poly[0], c = poly[k + 1] - poly[0];
      if (a.x * std::int64_t(c.y) - a.y * std::int64_t(c.x) == 0) continue;  // degenerate
      mesh.indices.push_back(v0);
      mesh.indices.push_back(vertex(poly[k]));
      mesh.indices.push_back(vertex(poly[k + 1]));
    }
  }
  mesh.max_error_m = max_err;
  mesh.triangle_count = int(mesh.indices.size() / 3);
  mesh.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return mesh;
}

}  // namespace ig::lod
