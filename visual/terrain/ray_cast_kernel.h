#pragma once
// The arithmetic every terrain ray cast shares (cast_ray's pyramid traversal
// and cast_ray_dda's cell walk, terrain/ray_cast.h): the prepared ray, the
// watertight triangle test, box (slab) tests and the on-surface rule. Only
// the ray cast sources include it.
//
// The watertight property relies on every shared quantity (a vertex's
// ray-space coordinates, an edge's edge function) being computed by the same
// operations wherever it is used. Fused multiply-add contraction could break
// that (one copy fused, another not), so it is switched off for every source
// that includes this header, from here on.
#if defined(__clang__)
#pragma clang fp contract(off)
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif

#include "terrain/ray_cast.h"

#include "terrain/earth_curvature.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

namespace ig::terrain::ray_kernel {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Origins within this distance of the surface (vertically, or along the ray)
// count as on it: rounding makes the sign of such a t meaningless.
constexpr double kSurfaceEpsM = 1e-9;
// Relative slack on box (slab) tests so rounding can never cull a box that
// the triangle test would hit; it only makes culling slightly conservative.
constexpr double kBoxSlackRel = 1e-10;

// A ray prepared once for slab tests and for the watertight triangle test
// (Woop, Benthin & Wald, "Watertight Ray/Triangle Intersection", JCGT 2013):
// translate vertices to the ray origin, permute so the dominant direction
// axis is kz, shear so the ray becomes the +Z axis. Then the ray hits a
// triangle iff the 2D origin lies inside its projected (X, Y) triangle.
struct Ray {
  glm::dvec3 o{}, d{};  // origin, unit direction
  double inv[3]{};      // 1 / d per axis where par[a] is false
  bool par[3]{};        // d[a] == 0 (or 1/d[a] overflows): no slab, a range test
  int kx = 0, ky = 1, kz = 2;
  double sx = 0, sy = 0, sz = 1;
  double mx[3]{}, my[3]{}, mz[3]{};  // rows of the permute + shear transform
  double t_lo = -kSurfaceEpsM;  // smallest t accepted (then clamped to 0)
  double slack_abs = 0;         // absolute slack (metres) for box tests
  Curvature curve;              // radius_m 0: flat
  // 1 / 2R and 1 / R^2 for the box bounds (0: R outside [1 m, 1e100 m], where
  // they could overflow; the exact drop is taken instead).
  double half_inv_r = 0, inv_r2 = 0;
};

// A sample's height as drawn for the ray's curvature centre. A pure function
// of (x, y): every cell sharing the sample lowers it bit for bit alike, so
// the watertight edge test still holds.
inline double drawn_height(const Ray& r, double x, double y, double h) {
  if (r.curve.radius_m <= 0.0) return h;
  const double dx = x - r.curve.centre_x, dy = y - r.curve.centre_y;
  return h - curvature_drop_squared(dx * dx + dy * dy, r.curve.radius_m);
}

// A box's height range [lo, hi] over footprint [x0, x1] x [y0, y1] as drawn:
// lowered by at least the drop at its farthest corner (lo) and at most the
// drop at its nearest point (hi), widened by a hair so rounding of the
// per-sample drops cannot leave it. The drop's bounds need no square root or
// division (they run for every node tested): with x = d^2 / R^2 <= 1,
//   d^2 / 2R  <=  drop(d) = d^2 / (R + sqrt(R^2 - d^2))  <=  d^2 / 2R * (1 + x)
// (the upper one as (1 + x)(1 + sqrt(1 - x)) >= 2); they differ by about
// 3 d^4 / 8 R^3, 0.2 mm at 20 km, which only loosens the box a little.
inline void drawn_range(const Ray& r, double x0, double x1, double y0, double y1, double& lo, double& hi) {
  if (r.curve.radius_m <= 0.0) return;
  const double cx = r.curve.centre_x, cy = r.curve.centre_y;
  const double nx = std::max({x0 - cx, 0.0, cx - x1}), ny = std::max({y0 - cy, 0.0, cy - y1});
  const double fx = std::max(std::abs(x0 - cx), std::abs(x1 - cx)), fy = std::max(std::abs(y0 - cy), std::abs(y1 - cy));
  const double r2 = r.curve.radius_m * r.curve.radius_m;
  const double far2 = std::min(fx * fx + fy * fy, r2), near2 = std::min(nx * nx + ny * ny, r2);
  const bool products = r.half_inv_r > 0.0;
  const double far = products ? far2 * r.half_inv_r * (1.0 + far2 * r.inv_r2) : curvature_drop_squared(far2, r.curve.radius_m);
  const double near = products ? near2 * r.half_inv_r : curvature_drop_squared(near2, r.curve.radius_m);
  lo -= far + 1e-9 * (1.0 + far);
  hi -= near - 1e-9 * (1.0 + near);
}

// Rejects NaN/inf/zero input; normalises dir.
inline bool make_ray(glm::dvec3 origin, glm::dvec3 dir, double max_t, double scene_scale, Ray& r) {
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(origin[a]) || !std::isfinite(dir[a])) return false;
  if (std::isnan(max_t) || max_t < 0) return false;
  // Scale by the largest component first so the length neither overflows
  // nor underflows.
  const double m = std::max({std::abs(dir.x), std::abs(dir.y), std::abs(dir.z)});
  if (m == 0) return false;
  dir /= m;
  dir /= std::sqrt(dir.x * dir.x + dir.y * dir.y + dir.z * dir.z);
  r.o = origin;
  r.d = dir;
  for (int a = 0; a < 3; ++a) {
    r.par[a] = true;
    if (dir[a] != 0) {
      const double inv = 1.0 / dir[a];
      if (std::isfinite(inv)) {
        r.inv[a] = inv;
        r.par[a] = false;
      }
    }
  }
  const double ax = std::abs(dir.x), ay = std::abs(dir.y), az = std::abs(dir.z);
  r.kz = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
  r.kx = (r.kz + 1) % 3;
  r.ky = (r.kx + 1) % 3;
  r.sx = dir[r.kx] / dir[r.kz];
  r.sy = dir[r.ky] / dir[r.kz];
  r.sz = 1.0 / dir[r.kz];
  r.mx[r.kx] = 1;
  r.mx[r.kz] = -r.sx;
  r.my[r.ky] = 1;
  r.my[r.kz] = -r.sy;
  r.mz[r.kz] = r.sz;
  const double o_mag = std::max({std::abs(origin.x), std::abs(origin.y), std::abs(origin.z)});
  r.slack_abs = 1e-12 * (1.0 + std::max(o_mag, scene_scale));
  return true;
}

// Vertex in ray space: (X, Y) is its 2D position relative to the ray, Z its
// depth along the ray scaled so that t = barycentric-weighted Z.
struct RVtx {
  double x, y, z;
};

// X = p[kx] - sx * p[kz], Y = p[ky] - sy * p[kz], Z = sz * p[kz] with p the
// vertex relative to the origin, written with per-ray coefficient rows (0, 1
// or the shear) so no runtime indexing is needed; the extra terms are exact
// zeros, so every vertex is transformed by the same arithmetic.
inline RVtx to_ray_space(const Ray& r, double px, double py, double pz) {
  const double x = px - r.o.x, y = py - r.o.y, z = pz - r.o.z;
  return {x * r.mx[0] + y * r.mx[1] + z * r.mx[2], x * r.my[0] + y * r.my[1] + z * r.my[2],
          x * r.mz[0] + y * r.mz[1] + z * r.mz[2]};
}

// Edge function of directed edge a->b at the ray (2D origin): twice the
// signed area of (ray, a, b). Always evaluated with the edge's canonical
// direction (see intersect_cell) so that neighbours sharing the edge get
// bit-identical values with opposite signs.
inline double edge_fn(const RVtx& a, const RVtx& b) { return a.x * b.y - a.y * b.x; }

// u, v, w: edge functions opposite vertices a, b, c (unnormalised barycentric
// weights of the ray's point). Inclusive: all >= 0 or all <= 0 is a hit, so
// edges and vertices belong to every triangle that shares them.
inline bool hit_triangle(double u, double v, double w, double az, double bz, double cz, const Ray& r,
                         double& t_best) {
  if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return false;
  const double det = u + v + w;
  if (det == 0) return false;  // ray parallel to the triangle's plane
  const double t = (u * az + v * bz + w * cz) / det;
  if (!(t >= r.t_lo) || t > t_best) return false;
  t_best = std::max(t, 0.0);
  return true;
}

// Both triangles of cell (i, j). On a hit with t <= t_best, lowers t_best.
inline bool intersect_cell(const Heightfield& hf, const Ray& r, int i, int j, double& t_best) {
  const double x0 = double(i) * hf.spacing_x_m, x1 = double(i + 1) * hf.spacing_x_m;
  const double y0 = double(j) * hf.spacing_y_m, y1 = double(j + 1) * hf.spacing_y_m;
  float h[4];  // (i, j), (i+1, j), (i, j+1), (i+1, j+1)
  if (hf.paged) {
    h[0] = hf.at(i, j), h[1] = hf.at(i + 1, j), h[2] = hf.at(i, j + 1), h[3] = hf.at(i + 1, j + 1);
  } else {
    const float* row0 = hf.heights.data() + static_cast<std::size_t>(j) * hf.width + i;
    const float* row1 = row0 + hf.width;
    h[0] = row0[0], h[1] = row0[1], h[2] = row1[0], h[3] = row1[1];
  }
  const RVtx p00 = to_ray_space(r, x0, y0, drawn_height(r, x0, y0, h[0]));
  const RVtx p10 = to_ray_space(r, x1, y0, drawn_height(r, x1, y0, h[1]));
  const RVtx p01 = to_ray_space(r, x0, y1, drawn_height(r, x0, y1, h[2]));
  const RVtx p11 = to_ray_space(r, x1, y1, drawn_height(r, x1, y1, h[3]));
  // Canonical edge directions: west->east, south->north, and the diagonal
  // (i,j)->(i+1,j+1). The east edge here is the west edge of cell i+1 and the
  // north edge is the south edge of cell j+1, computed identically there.
  const double e_s = edge_fn(p00, p10);  // south
  const double e_n = edge_fn(p01, p11);  // north
  const double e_w = edge_fn(p00, p01);  // west
  const double e_e = edge_fn(p10, p11);  // east
  const double e_d = edge_fn(p00, p11);  // diagonal
  bool hit = false;
  // Triangle (p00, p10, p11): weights E(p10,p11), E(p11,p00), E(p00,p10).
  hit |= hit_triangle(e_e, -e_d, e_s, p00.z, p10.z, p11.z, r, t_best);
  // Triangle (p00, p11, p01): weights E(p11,p01), E(p01,p00), E(p00,p11).
  hit |= hit_triangle(-e_n, -e_w, e_d, p00.z, p11.z, p01.z, r, t_best);
  return hit;
}

inline double slack(const Ray& r, double t) { return kBoxSlackRel * std::abs(t) + r.slack_abs; }
// enter - slack(enter) <= exit + slack(exit), i.e. the interval is not
// empty up to rounding.
// Infinite bounds (a parallel axis outside its slab gives [inf, -inf]) must
// not be excused by an infinite slack.
inline bool overlaps(const Ray& r, double enter, double exit) {
  if (enter <= exit) return true;
  const double gap = enter - exit;
  return std::isfinite(gap) && gap <= kBoxSlackRel * (std::abs(enter) + std::abs(exit)) + 2 * r.slack_abs;
}

// One axis of a slab test; false when the ray cannot be inside [lo, hi].
inline bool slab(const Ray& r, int a, double lo, double hi, double& enter, double& exit) {
  if (r.par[a]) return r.o[a] >= lo - r.slack_abs && r.o[a] <= hi + r.slack_abs;
  double t0 = (lo - r.o[a]) * r.inv[a];
  double t1 = (hi - r.o[a]) * r.inv[a];
  if (t0 > t1) std::swap(t0, t1);
  enter = std::max(enter, t0);
  exit = std::min(exit, t1);
  return true;
}

// Range of t over which one axis coordinate stays within a slab; for an
// axis the ray is parallel to, everything or nothing.
struct Span {
  double in, out;
};

// Spans for the n (1 or 2) consecutive slabs [planes[k], planes[k+1]] of axis a.
inline void axis_spans(const Ray& r, int a, const double planes[3], int n, Span out[2]) {
  if (r.par[a]) {
    for (int k = 0; k < n; ++k) {
      const bool inside = r.o[a] >= planes[k] - r.slack_abs && r.o[a] <= planes[k + 1] + r.slack_abs;
      out[k] = inside ? Span{-kInf, kInf} : Span{kInf, -kInf};
    }
    return;
  }
  // Scalars, not a loop over an array: the compiler stored such an array and
  // read it back in pairs, a load that waits for the stores to retire.
  const double o = r.o[a], inv = r.inv[a];
  const double t0 = (planes[0] - o) * inv, t1 = (planes[1] - o) * inv;
  out[0] = Span{std::min(t0, t1), std::max(t0, t1)};
  if (n == 2) {
    const double t2 = (planes[2] - o) * inv;
    out[1] = Span{std::min(t1, t2), std::max(t1, t2)};
  }
}

// Ray vs axis-aligned box, clipped to [t_lo, t_max]. On success gives the
// 2D (footprint only) entry t, used to order siblings, and a conservative
// (slack-lowered) 3D entry t, used to prune against the best hit so far.
inline bool box_test(const Ray& r, double x0, double x1, double y0, double y1, double z0, double z1,
                     double t_max, double& t2d, double& key) {
  double enter = r.t_lo, exit = t_max;
  if (!slab(r, 0, x0, x1, enter, exit) || !slab(r, 1, y0, y1, enter, exit)) return false;
  t2d = enter;
  if (!slab(r, 2, z0, z1, enter, exit)) return false;
  key = enter - slack(r, enter);
  return overlaps(r, enter, exit);
}

inline bool valid_spacing(const Heightfield& hf) {
  return std::isfinite(hf.spacing_x_m) && std::isfinite(hf.spacing_y_m) && hf.spacing_x_m > 0 &&
         hf.spacing_y_m > 0;
}

inline double scene_scale(const Heightfield& hf, double zmin, double zmax) {
  return std::max({hf.extent_x_m(), hf.extent_y_m(), std::abs(zmin), std::abs(zmax)});
}

inline std::optional<RayHit> make_hit(const Ray& r, double t, int i, int j) {
  return RayHit{t, r.o + t * r.d, i, j};
}

// An origin on the surface (vertically within kSurfaceEpsM, inside the
// footprint) is a hit at t = 0 whatever the direction. Without this rule,
// an origin on an edge with the ray leaving on the convex side (a touch, not
// a crossing) would be hit or missed at the whim of rounding.
//
// The rule for one cell (cast_ray checks it on the cells whose box contains
// the origin): the origin is inside the closed footprint of cell (i, j) and
// within kSurfaceEpsM vertically of the cell's surface.
inline bool origin_on_cell_surface(const Heightfield& hf, const Ray& r, int i, int j) {
  const double sx = hf.spacing_x_m, sy = hf.spacing_y_m;
  const double fx = (r.o.x - double(i) * sx) / sx, fy = (r.o.y - double(j) * sy) / sy;
  constexpr double kTol = 1e-12;
  if (fx < -kTol || fx > 1 + kTol || fy < -kTol || fy > 1 + kTol) return false;
  const double u = std::clamp(fx, 0.0, 1.0), v = std::clamp(fy, 0.0, 1.0);
  const double x0 = double(i) * sx, x1 = double(i + 1) * sx, y0 = double(j) * sy, y1 = double(j + 1) * sy;
  const double h00 = drawn_height(r, x0, y0, hf.at(i, j)), h10 = drawn_height(r, x1, y0, hf.at(i + 1, j));
  const double h01 = drawn_height(r, x0, y1, hf.at(i, j + 1)), h11 = drawn_height(r, x1, y1, hf.at(i + 1, j + 1));
  const double h = u >= v ? h00 + (h10 - h00) * u + (h11 - h10) * v : h00 + (h01 - h00) * v + (h11 - h01) * u;
  return std::abs(r.o.z - h) <= kSurfaceEpsM;
}

// The same rule for the whole footprint (cast_ray_dda checks it up front).
inline std::optional<RayHit> origin_on_surface(const Heightfield& hf, const Ray& r) {
  const double ex = hf.extent_x_m(), ey = hf.extent_y_m();
  if (!(r.o.x >= 0 && r.o.x <= ex && r.o.y >= 0 && r.o.y <= ey)) return std::nullopt;
  if (std::abs(r.o.z - hf.sample_surface(r.o.x, r.o.y)) > kSurfaceEpsM) return std::nullopt;
  const int i = std::clamp(int(r.o.x / hf.spacing_x_m), 0, hf.width - 2);
  const int j = std::clamp(int(r.o.y / hf.spacing_y_m), 0, hf.height - 2);
  return RayHit{0.0, r.o, i, j};
}

}  // namespace ig::terrain::ray_kernel
