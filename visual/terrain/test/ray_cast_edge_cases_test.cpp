// cast_ray and cast_ray_dda (terrain/ray_cast.h) at their edges: rays along
// grid lines and diagonals (watertightness), bounded traversal work, origins
// outside the footprint or below the surface, sky rays, max_t, bad input.
#include <gtest/gtest.h>

#include "terrain/test/ray_cast_test_support.h"

namespace {

using namespace ray_cast_test;

// Rays in the vertical plane of a grid row, a grid column or a line of cell
// diagonals: they meet the surface exactly on shared edges and vertices,
// where a non-watertight test would let them slip through. The reference is
// the first crossing of the ray with the piecewise-linear height profile
// along that line (long double); crossings are transversal, so unambiguous.
TEST(RayCast, RaysAlongGridLinesAndDiagonals) {
  const Heightfield hf = random_hf(33, 29, 10.0, 7.0, 17);
  const HeightPyramid pyr(hf);
  Uniform01 u01(71);
  int hits = 0, n = 0;
  for (int k = 0; k < 3000; ++k) {
    // Line of vertices p(u) = base + u * step, u = 0..count-1.
    int bi = 0, bj = 0, si = 0, sj = 0, count = 0;
    const int kind = k % 3;
    if (kind == 0) {  // row j
      bj = int(u01() * hf.height), si = 1, count = hf.width;
    } else if (kind == 1) {  // column i
      bi = int(u01() * hf.width), sj = 1, count = hf.height;
    } else {  // diagonal through (bi, 0) or (0, bj)
      if (u01() < 0.5) bi = int(u01() * (hf.width - 1)); else bj = int(u01() * (hf.height - 1));
      si = sj = 1;
      count = std::min(hf.width - bi, hf.height - bj);
    }
    const bool reverse = u01() < 0.5;
    auto vertex_h = [&](int u) { return LD(hf.at(bi + u * si, bj + u * sj)); };
    const LD step_len = std::hypot(LD(si * hf.spacing_x_m), LD(sj * hf.spacing_y_m));
    // Ray in parameter u (may start before/after the line: outside the footprint).
    const LD u0 = LD(-3 + (count + 5) * u01());
    const LD z0 = LD(hf.min_m - 20 + (hf.max_m - hf.min_m + 40) * u01());
    const LD dz_du = LD((u01() - 0.5) * 2 * (u01() < 0.3 ? 0.05 : 30.0));  // shallow or steep
    const LD du = reverse ? -1 : 1;
    const dvec3 o{double((bi + u0 * si) * hf.spacing_x_m), double((bj + u0 * sj) * hf.spacing_y_m), double(z0)};
    const dvec3 d{double(du * si * hf.spacing_x_m), double(du * sj * hf.spacing_y_m), double(du * dz_du)};
    // Use the rounded origin/direction for the reference.
    const LD uo = si ? (LD(o.x) / hf.spacing_x_m - bi) : (LD(o.y) / hf.spacing_y_m - bj);
    const LD zo = LD(o.z), slope = LD(d.z) / du;  // dz per unit u along the ray
    // f(u) = ray z - profile z; find the first zero at u >= uo (in ray direction).
    auto f = [&](LD u) {
      const int a = std::clamp(int(std::floor(u)), 0, count - 2);
      const LD w = u - a;
      return zo + (u - uo) * slope - (vertex_h(a) * (1 - w) + vertex_h(a + 1) * w);
    };
    std::optional<LD> u_hit;
    const LD u_start = std::clamp(uo, LD(0), LD(count - 1));
    if (uo >= 0 && uo <= count - 1 && f(uo) == 0) u_hit = uo;
    // Breakpoints in ray order.
    LD prev = u_start;
    const bool origin_inside = uo >= 0 && uo <= count - 1;
    if (!origin_inside && ((uo < 0) == reverse)) prev = -1;  // pointing away from the line: no hit
    if (!u_hit && prev >= 0) {
      for (;;) {
        LD next = reverse ? std::ceil(prev) - 1 : std::floor(prev) + 1;
        if (next < 0 || next > count - 1) break;
        const LD fa = f(prev), fb = f(next);
        if ((fa <= 0 && fb >= 0) || (fa >= 0 && fb <= 0)) {
          u_hit = (fa == fb) ? prev : prev + (next - prev) * fa / (fa - fb);
          break;
        }
        prev = next;
      }
    }
    ++n;
    const auto got = cast_ray(hf, pyr, o, d);
    const auto got_dda = cast_ray_dda(hf, o, d);
    if (!u_hit) {
      EXPECT_FALSE(got.has_value()) << "kind " << kind << " k " << k << " t " << got->t;
      EXPECT_FALSE(got_dda.has_value()) << "kind " << kind << " k " << k;
      continue;
    }
    ++hits;
    // Metres of ray per unit of u.
    const LD t_per_u = std::sqrt(step_len * step_len + slope * slope);
    const double t_want = double(std::abs(*u_hit - uo) * t_per_u);
    ASSERT_TRUE(got.has_value()) << "kind " << kind << " k " << k << " t_want " << t_want;
    EXPECT_NEAR(got->t, t_want, 1e-9 * std::max(1.0, t_want)) << "kind " << kind << " k " << k;
    ASSERT_TRUE(got_dda.has_value()) << "kind " << kind << " k " << k << " t_want " << t_want;
    EXPECT_NEAR(got_dda->t, t_want, 1e-9 * std::max(1.0, t_want)) << "kind " << kind << " k " << k;
  }
  std::printf("[grid lines] rays=%d hits=%d\n", n, hits);
  EXPECT_GT(hits, n / 4);
}

// Work bounds (deterministic counts, not timings): rays parallel to an axis
// must still be culled by the pyramid, not walk the whole tree.
TEST(RayCast, TraversalWorkIsBounded) {
  const Heightfield hf = random_hf(513, 385, 30.0, 30.0, 23);
  const HeightPyramid pyr(hf);
  Uniform01 u01(91);
  const int levels = pyr.num_levels();
  for (dvec3 d : {dvec3{0, 0, -1}, dvec3{0, 0, 1}, dvec3{1, 0, -0.05}, dvec3{0, -1, -0.05}, dvec3{1, 0, 0},
                  dvec3{0.6, 0.8, -0.05}, dvec3{1, 1, -0.3}}) {
    long nodes = 0, cells = 0, worst_nodes = 0, worst_cells = 0;
    for (int k = 0; k < 300; ++k) {
      // On grid lines/corners half of the time (ties between siblings).
      double x = hf.extent_x_m() * u01(), y = hf.extent_y_m() * u01();
      if (k % 2) {
        x = std::round(x / hf.spacing_x_m) * hf.spacing_x_m;
        y = std::round(y / hf.spacing_y_m) * hf.spacing_y_m;
      }
      const dvec3 o{x, y, hf.max_m + 1 + 20 * u01()};
      ig::terrain::RayCastStats stats;
      const auto h = cast_ray(hf, pyr, o, d, kInf, stats);
      const auto plain = cast_ray(hf, pyr, o, d);
      ASSERT_EQ(h.has_value(), plain.has_value());
      if (h) {
        EXPECT_EQ(h->t, plain->t);
      }
      nodes += stats.nodes_tested;
      cells += stats.cells_tested;
      worst_nodes = std::max<long>(worst_nodes, stats.nodes_tested);
      worst_cells = std::max<long>(worst_cells, stats.cells_tested);
    }
    std::printf("[work] d=(%g,%g,%g) mean nodes %.1f cells %.1f, worst %ld / %ld\n", d.x, d.y, d.z, nodes / 300.0,
                cells / 300.0, worst_nodes, worst_cells);
    if (d.x == 0 && d.y == 0) {  // vertical: one path down (4 on a shared corner)
      EXPECT_LE(worst_nodes, 4 * levels + 1);
      EXPECT_LE(worst_cells, 4);
    } else {
      EXPECT_LE(nodes / 300.0, 60.0 * levels);
      EXPECT_LE(worst_nodes, 400 * levels);
    }
  }
}

TEST(RayCast, RaysFromOutsideTheFootprint) {
  CheckedRays rays(random_hf(33, 33, 10.0, 10.0, 6), 41, "outside");
  const Heightfield& hf = rays.hf;
  Uniform01& u01 = rays.u01;
  int hits = 0;
  for (int k = 0; k < 1500; ++k) {
    const double ex = hf.extent_x_m(), ey = hf.extent_y_m();
    // A point beyond one of the four sides, at or below terrain height.
    const double s = u01() * 4, along = u01();
    dvec3 o = s < 1   ? dvec3{-20 - 200 * u01(), along * ey, 0}
              : s < 2 ? dvec3{ex + 20 + 200 * u01(), along * ey, 0}
              : s < 3 ? dvec3{along * ex, -20 - 200 * u01(), 0}
                      : dvec3{along * ex, ey + 20 + 200 * u01(), 0};
    o.z = hf.min_m - 20 + (hf.max_m - hf.min_m + 60) * u01();
    const double x = ex * u01(), y = ey * u01();
    const dvec3 target{x, y, hf.sample_surface(x, y)};
    const dvec3 d = target - o;
    const auto h = rays.cast(o, d);
    // Aimed at a surface point: must hit no later than it (or it, from
    // outside the footprint when coming in below the edge it may hit the
    // underside first; either way, a hit).
    if (h) {
      ++hits;
      EXPECT_LE(h->t, glm::length(d) * (1 + 1e-9) + 1e-9);
    }
  }
  EXPECT_GT(hits, 1400);  // misses only when the target is barely grazed
  rays.expect_clean();
}

TEST(RayCast, RaysFromBelowTheSurface) {
  CheckedRays rays(random_hf(33, 33, 10.0, 10.0, 7), 51, "below");
  const Heightfield& hf = rays.hf;
  Uniform01& u01 = rays.u01;
  for (int k = 0; k < 1500; ++k) {
    const double x = hf.extent_x_m() * u01(), y = hf.extent_y_m() * u01();
    const double surf = hf.sample_surface(x, y);
    const dvec3 o{x, y, surf - 1e-3 - 30 * u01()};
    const double z = 2 * u01() - 1, phi = 2 * M_PI * u01(), r = std::sqrt(1 - z * z);
    const dvec3 d{r * std::cos(phi), r * std::sin(phi), z};
    rays.cast(o, d);
    // Straight up from below: the surface directly above.
    const auto up = cast_ray(hf, rays.pyr, o, {0, 0, 1});
    ASSERT_TRUE(up.has_value());
    EXPECT_NEAR(up->point.z, surf, 1e-9 * std::max(1.0, std::abs(surf)));
  }
  rays.expect_clean();
}

TEST(RayCast, SkyRaysMiss) {
  const Heightfield hf = random_hf(65, 47, 10.0, 10.0, 8);
  const HeightPyramid pyr(hf);
  Uniform01 u01(61);
  for (int k = 0; k < 2000; ++k) {
    const dvec3 o{hf.extent_x_m() * (1.4 * u01() - 0.2), hf.extent_y_m() * (1.4 * u01() - 0.2),
                  hf.max_m + 0.01 + 100 * u01()};
    const double elev = std::asin(1e-6 + (1 - 1e-6) * u01()), az = 2 * M_PI * u01();
    const dvec3 d{std::cos(az) * std::cos(elev), std::sin(az) * std::cos(elev), std::sin(elev)};
    EXPECT_FALSE(cast_ray(hf, pyr, o, d).has_value());
  }
}

TEST(RayCast, StartOnSurfaceAndMaxT) {
  const Heightfield hf = random_hf(17, 17, 10.0, 10.0, 9);
  const HeightPyramid pyr(hf);
  // Origin exactly on a vertex: t = 0 (documented).
  const dvec3 v{50, 60, hf.at(5, 6)};
  for (dvec3 d : {dvec3{1, 0, 0}, dvec3{0, 0, 1}, dvec3{0.3, -0.2, 0.9}}) {
    const auto h = cast_ray(hf, pyr, v, d);
    ASSERT_TRUE(h.has_value());
    EXPECT_EQ(h->t, 0.0);
  }
  // Origin on an edge, a diagonal or inside a cell, on the surface (to
  // rounding): t = 0 whatever the direction (documented), also for rays
  // leaving a convex ridge edge, which only touch the surface there.
  Uniform01 u01(101);
  for (int k = 0; k < 200; ++k) {
    const int i = int(u01() * 15), j = int(u01() * 15);
    const double fx = k % 3 == 0 ? 0.5 : u01(), fy = k % 3 == 1 ? 0.0 : (k % 3 == 2 ? fx : u01());
    const double x = (i + fx) * 10.0, y = (j + fy) * 10.0;
    const dvec3 o{x, y, hf.sample_surface(x, y)};
    const double z = 2 * u01() - 1, phi = 2 * M_PI * u01(), r = std::sqrt(1 - z * z);
    const dvec3 d{r * std::cos(phi), r * std::sin(phi), z};
    const auto h = cast_ray(hf, pyr, o, d);
    ASSERT_TRUE(h.has_value()) << k;
    EXPECT_EQ(h->t, 0.0) << k;
    const auto hd = cast_ray_dda(hf, o, d);
    ASSERT_TRUE(hd.has_value()) << k;
    EXPECT_EQ(hd->t, 0.0) << k;
    // 1 mm above, pointing up: not on the surface any more.
    const auto up = cast_ray(hf, pyr, o + dvec3{0, 0, 1e-3}, {0, 0, 1});
    EXPECT_FALSE(up.has_value()) << k;
  }
  // max_t cuts off; exactly at the hit still hits.
  const dvec3 o{55, 63, hf.max_m + 5};
  const auto full = cast_ray(hf, pyr, o, {0.1, 0.2, -1});
  ASSERT_TRUE(full.has_value());
  EXPECT_FALSE(cast_ray(hf, pyr, o, {0.1, 0.2, -1}, full->t * 0.999).has_value());
  EXPECT_TRUE(cast_ray(hf, pyr, o, {0.1, 0.2, -1}, full->t * 1.000001).has_value());
  EXPECT_TRUE(cast_ray(hf, pyr, {55, 63, hf.at(5, 6) + 5.0}, {0, 0, -1}, kInf).has_value());
}

TEST(RayCast, InvalidInput) {
  const Heightfield hf = random_hf(9, 9, 1.0, 1.0, 10);
  const HeightPyramid pyr(hf);
  const dvec3 o{4, 4, 1000};
  EXPECT_FALSE(cast_ray(hf, pyr, o, {0, 0, 0}).has_value());
  EXPECT_FALSE(cast_ray(hf, pyr, {kNaN, 4, 1000}, {0, 0, -1}).has_value());
  EXPECT_FALSE(cast_ray(hf, pyr, o, {0, kNaN, -1}).has_value());
  EXPECT_FALSE(cast_ray(hf, pyr, o, {0, 0, -kInf}).has_value());
  EXPECT_FALSE(cast_ray(hf, pyr, {kInf, 4, 1000}, {0, 0, -1}).has_value());
  EXPECT_FALSE(cast_ray(hf, pyr, o, {0, 0, -1}, kNaN).has_value());
  EXPECT_FALSE(cast_ray(hf, pyr, o, {0, 0, -1}, -1.0).has_value());
  EXPECT_FALSE(cast_ray_dda(hf, o, {0, 0, 0}).has_value());
  EXPECT_FALSE(cast_ray_dda(hf, {kNaN, 0, 0}, {0, 0, -1}).has_value());
  EXPECT_TRUE(cast_ray(hf, pyr, o, {0, 0, -1}).has_value());
  // Tiny and huge direction vectors are normalised safely.
  EXPECT_TRUE(cast_ray(hf, pyr, o, {0, 0, -1e-300}).has_value());
  EXPECT_TRUE(cast_ray(hf, pyr, o, {1e-310, 0, -1e300}).has_value());
  // A pyramid from another heightfield is a programming error.
  const HeightPyramid other(random_hf(10, 9, 1.0, 1.0, 10));
  EXPECT_THROW(cast_ray(hf, other, o, {0, 0, -1}), std::invalid_argument);
  EXPECT_THROW(cast_ray(hf, HeightPyramid{}, o, {0, 0, -1}), std::invalid_argument);
  // No cells: no surface.
  const Heightfield line = make_hf(1, 4, 1, 1, [](int, int) { return 0.f; });
  EXPECT_FALSE(cast_ray(line, HeightPyramid(line), {0, 1, 10}, {0, 0, -1}).has_value());
}

}  // namespace
