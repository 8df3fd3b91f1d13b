#pragma once
// Shared helpers of the ray cast tests (height_pyramid_test.cpp,
// ray_cast_test.cpp, ray_cast_edge_cases_test.cpp; header only): test
// heightfields and an independent brute-force reference (every triangle,
// Moller-Trumbore in long double) with the random-ray comparison.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <tuple>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "terrain/height_pyramid.h"
#include "terrain/heightfield.h"
#include "terrain/ray_cast.h"

namespace ray_cast_test {

using namespace ig::terrain;
using glm::dvec3;
using LD = long double;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Uniform numbers in [0, 1) from one seeded generator.
class Uniform01 {
 public:
  explicit Uniform01(unsigned seed) : rng_(seed) {}
  double operator()() { return dist_(rng_); }

 private:
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> dist_{0.0, 1.0};
};

inline Heightfield make_hf(int w, int h, double sx, double sy, const std::function<float(int, int)>& f) {
  Heightfield hf;
  hf.width = w;
  hf.height = h;
  hf.spacing_x_m = sx;
  hf.spacing_y_m = sy;
  hf.heights.resize(static_cast<std::size_t>(w) * h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) hf.ref(i, j) = f(i, j);
  hf.finalize_stats();
  return hf;
}

// Rough terrain with big slopes: smooth hills plus per-sample noise.
inline Heightfield random_hf(int w, int h, double sx, double sy, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> noise(-40.f, 40.f);
  return make_hf(w, h, sx, sy, [&](int i, int j) {
    return float(100.0 + 60.0 * std::sin(i * 0.37) * std::cos(j * 0.29) + noise(rng));
  });
}

// ---------------------------------------------------------------- reference

struct RefHit {
  bool hit = false;
  LD t = 0;
  int i = -1, j = -1;
};

struct LV {
  LD x, y, z;
};
inline LV sub(LV a, LV b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline LV cross(LV a, LV b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline LD dot(LV a, LV b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Every triangle of the rendered surface, nearest hit with 0 <= t <= max_t,
// touching edges included. Independent of the code under test.
inline RefHit brute_force(const Heightfield& hf, dvec3 o_in, dvec3 d_in, double max_t = kInf) {
  RefHit best;
  LV o{o_in.x, o_in.y, o_in.z};
  const LD len = std::sqrt(LD(d_in.x) * d_in.x + LD(d_in.y) * d_in.y + LD(d_in.z) * d_in.z);
  LV d{d_in.x / len, d_in.y / len, d_in.z / len};
  auto vtx = [&](int i, int j) { return LV{LD(i) * hf.spacing_x_m, LD(j) * hf.spacing_y_m, LD(hf.at(i, j))}; };
  auto tri = [&](LV a, LV b, LV c, int i, int j) {
    const LV e1 = sub(b, a), e2 = sub(c, a);
    const LV p = cross(d, e2);
    const LD det = dot(e1, p);
    if (det == 0) return;
    const LV s = sub(o, a);
    const LD u = dot(s, p) / det;
    const LV q = cross(s, e1);
    const LD v = dot(d, q) / det;
    if (u < 0 || v < 0 || u + v > 1) return;
    const LD t = dot(e2, q) / det;
    if (t < 0 || t > max_t) return;
    if (!best.hit || t < best.t) best = RefHit{true, t, i, j};
  };
  for (int j = 0; j + 1 < hf.height; ++j)
    for (int i = 0; i + 1 < hf.width; ++i) {
      tri(vtx(i, j), vtx(i + 1, j), vtx(i + 1, j + 1), i, j);
      tri(vtx(i, j), vtx(i + 1, j + 1), vtx(i, j + 1), i, j);
    }
  return best;
}

// Horizontal distance from (x, y) to the nearest triangle edge line of the
// cell containing it (grid lines and the cell diagonal).
inline double dist_to_edges(const Heightfield& hf, double x, double y) {
  const double gx = std::clamp(x / hf.spacing_x_m, 0.0, double(hf.width - 1));
  const double gy = std::clamp(y / hf.spacing_y_m, 0.0, double(hf.height - 1));
  const double fx = gx - std::min(std::floor(gx), double(hf.width - 2));
  const double fy = gy - std::min(std::floor(gy), double(hf.height - 2));
  const double sx = hf.spacing_x_m, sy = hf.spacing_y_m;
  const double d_grid = std::min(std::min(fx, 1 - fx) * sx, std::min(fy, 1 - fy) * sy);
  const double d_diag = sx * sy * std::abs(fx - fy) / std::hypot(sx, sy);
  return std::min(d_grid, d_diag);
}

struct Stats {
  int rays = 0, hits = 0, ambiguous = 0, mismatches = 0;
  double max_rel_t_err = 0;
};

constexpr double kEdgeTol = 1e-9;  // metres: "grazes exactly along an edge"

// Compares one result with the reference; counts into st and reports
// mismatches as test failures (with the ray) but at most a few times.
inline void check_ray(const Heightfield& hf, const RefHit& ref, const std::optional<RayHit>& got, dvec3 o, dvec3 d,
               Stats& st, const char* what) {
  ++st.rays;
  if (ref.hit) ++st.hits;
  auto fail = [&](const char* why) {
    ++st.mismatches;
    if (st.mismatches <= 5)
      ADD_FAILURE() << what << ": " << why << " o=(" << o.x << "," << o.y << "," << o.z << ") d=(" << d.x
                    << "," << d.y << "," << d.z << ") ref=" << (ref.hit ? double(ref.t) : -1.0)
                    << " got=" << (got ? got->t : -1.0);
  };
  const dvec3 dn = glm::normalize(d);
  auto near_edge = [&](double t) {
    const dvec3 p = o + t * dn;
    return dist_to_edges(hf, p.x, p.y) <= kEdgeTol * std::max(1.0, std::max(hf.spacing_x_m, hf.spacing_y_m));
  };
  if (!ref.hit && !got) return;
  if (ref.hit && got) {
    const double tr = double(ref.t);
    const double err = std::abs(got->t - tr) / std::max(tr, 1.0);
    if (err <= 1e-6) {
      st.max_rel_t_err = std::max(st.max_rel_t_err, err);
      // The reported point and cell must agree with the surface.
      const dvec3 p = got->point;
      const double tol = 1e-6 * std::max(1.0, tr);
      if (std::abs(p.z - hf.sample_surface(p.x, p.y)) > 1e-5 * std::max(1.0, tr) ||
          p.x < got->cell_i * hf.spacing_x_m - tol || p.x > (got->cell_i + 1) * hf.spacing_x_m + tol ||
          p.y < got->cell_j * hf.spacing_y_m - tol || p.y > (got->cell_j + 1) * hf.spacing_y_m + tol)
        fail("hit point not on the surface / not in the reported cell");
      return;
    }
    // Different hits: the nearer one must be a touch at an edge.
    if (near_edge(std::min(tr, got->t))) {
      ++st.ambiguous;
      return;
    }
    fail("different t");
    return;
  }
  const double t = ref.hit ? double(ref.t) : got->t;
  if (near_edge(t)) {
    ++st.ambiguous;
    return;
  }
  fail(ref.hit ? "missed" : "false hit");
}

inline void expect_clean(const Stats& st, const char* what, int max_ambiguous = 0) {
  std::printf("[%s] rays=%d ref_hits=%d ambiguous=%d mismatches=%d max_rel_t_err=%.3g\n", what, st.rays,
              st.hits, st.ambiguous, st.mismatches, st.max_rel_t_err);
  EXPECT_EQ(st.mismatches, 0) << what;
  EXPECT_LE(st.ambiguous, max_ambiguous) << what;
}

// Rays cast over a DEM (cast_ray over its height pyramid), each checked
// against the brute-force reference and tallied under `what`, and the random
// source the test makes them from.
struct CheckedRays {
  CheckedRays(Heightfield dem, unsigned seed, const char* what)
      : hf(std::move(dem)), pyr(hf), u01(seed), what(what) {}

  // cast_ray from o along d, checked: what it hit.
  std::optional<RayHit> cast(dvec3 o, dvec3 d) {
    const auto h = cast_ray(hf, pyr, o, d);
    check_ray(hf, brute_force(hf, o, d), h, o, d, st, what);
    return h;
  }
  // No mismatch and no ambiguous touch among the rays cast.
  void expect_clean() const { ray_cast_test::expect_clean(st, what); }

  const Heightfield hf;
  const HeightPyramid pyr;
  Uniform01 u01;
  Stats st;
  const char* what;
};

// Random rays in and around the footprint at and below terrain heights,
// plus rays aimed at random surface points (so roughly half hit).
inline void random_rays(const Heightfield& hf, int n, unsigned seed, const char* what) {
  const HeightPyramid pyr(hf);
  Uniform01 u01(seed);
  const double ex = hf.extent_x_m(), ey = hf.extent_y_m();
  Stats st, st_dda;
  for (int k = 0; k < n; ++k) {
    dvec3 o{(-0.3 + 1.6 * u01()) * ex, (-0.3 + 1.6 * u01()) * ey,
            hf.min_m - 30 + (hf.max_m - hf.min_m + 130) * u01()};
    dvec3 d;
    if (k % 2 == 0) {  // uniform direction
      const double z = 2 * u01() - 1, phi = 2 * M_PI * u01(), r = std::sqrt(1 - z * z);
      d = {r * std::cos(phi), r * std::sin(phi), z};
    } else {  // aimed at a random surface point, not normalised
      const double x = ex * u01(), y = ey * u01();
      d = dvec3{x, y, hf.sample_surface(x, y)} - o;
      if (glm::length(d) == 0) continue;
    }
    const double max_t = (k % 7 == 3) ? glm::length(d) * u01() * 2 : kInf;
    const RefHit ref = brute_force(hf, o, d, max_t);
    check_ray(hf, ref, cast_ray(hf, pyr, o, d, max_t), o, d, st, what);
    check_ray(hf, ref, cast_ray_dda(hf, o, d, max_t), o, d, st_dda, what);
  }
  expect_clean(st, what);
  expect_clean(st_dda, (std::string(what) + " (dda)").c_str(), n / 500);
  EXPECT_GT(st.hits, n / 5);
}

}  // namespace ray_cast_test
