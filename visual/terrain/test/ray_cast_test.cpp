// cast_ray and cast_ray_dda (terrain/ray_cast.h) against an independent
// brute-force reference: random rays, distant origins, flat terrain, grazing
// rays, rays nearly parallel to a slope and vertical rays on shared edges.
// The remaining edge cases are ray_cast_edge_cases_test.cpp.
#include <gtest/gtest.h>

#include "terrain/test/ray_cast_test_support.h"

namespace {

using namespace ray_cast_test;

// ----------------------------------------------------------------- ray cast

TEST(RayCast, RandomRaysSquare) { random_rays(random_hf(33, 33, 10.0, 10.0, 1), 3000, 11, "33x33"); }

TEST(RayCast, RandomRaysNonSquare) { random_rays(random_hf(65, 47, 10.0, 10.0, 2), 1500, 12, "65x47"); }

TEST(RayCast, RandomRaysNonUniformSpacing) {
  random_rays(random_hf(41, 30, 30.0, 17.5, 3), 1500, 13, "41x30 spacing 30x17.5");
}

TEST(RayCast, RandomRaysTwoByTwo) {
  const Heightfield hf = make_hf(2, 2, 5.0, 3.0, [](int i, int j) { return float(10 + 7 * i - 4 * j + i * j * 3); });
  random_rays(hf, 3000, 14, "2x2");
}

TEST(RayCast, RandomRaysThinStrips) {
  random_rays(random_hf(2, 40, 10.0, 10.0, 16), 1500, 17, "2x40");
  random_rays(random_hf(40, 2, 10.0, 10.0, 18), 1500, 19, "40x2");
  random_rays(random_hf(3, 3, 10.0, 10.0, 20), 1500, 21, "3x3");
}

// Rays from 20-80 km away (a distant aircraft) aimed at surface points:
// the slack and the ray-space transform must cope with large coordinates.
TEST(RayCast, DistantOrigins) {
  CheckedRays rays(random_hf(33, 33, 30.0, 30.0, 22), 81, "distant");
  const Heightfield& hf = rays.hf;
  Uniform01& u01 = rays.u01;
  for (int k = 0; k < 1000; ++k) {
    const double dist = 20000 + 60000 * u01(), az = 2 * M_PI * u01();
    const dvec3 o{480 + dist * std::cos(az), 480 + dist * std::sin(az), hf.max_m + 3000 * u01() * u01()};
    const double x = hf.extent_x_m() * u01(), y = hf.extent_y_m() * u01();
    const dvec3 d = dvec3{x, y, hf.sample_surface(x, y)} - o;
    EXPECT_TRUE(rays.cast(o, d).has_value());
  }
  rays.expect_clean();
}

TEST(RayCast, FlatTerrain) {
  const Heightfield hf = make_hf(20, 13, 4.0, 6.0, [](int, int) { return 10.f; });
  random_rays(hf, 2000, 15, "flat");
  const HeightPyramid pyr(hf);
  Uniform01 u01(5);
  for (int k = 0; k < 500; ++k) {  // analytic: plane z = 10
    const dvec3 o{80 * u01() - 2, 80 * u01() - 2, 10 + 50 * (u01() - 0.3)};
    const dvec3 d{u01() - 0.5, u01() - 0.5, u01() - 0.5};
    const dvec3 dn = glm::normalize(d);
    const double t = (10 - o.z) / dn.z;
    const dvec3 p = o + t * dn;
    const bool inside = t >= 0 && p.x >= 0 && p.x <= hf.extent_x_m() && p.y >= 0 && p.y <= hf.extent_y_m();
    const auto h = cast_ray(hf, pyr, o, d);
    ASSERT_EQ(h.has_value(), inside) << k;
    if (h) {
      EXPECT_NEAR(h->t, t, 1e-9 * std::max(1.0, t));
    }
  }
  // Documented: a ray lying in the plane of flat ground does not hit it;
  // parallel rays just above/below never do.
  for (double dz : {0.0, 1e-9, -1e-9, 1e-3})
    EXPECT_FALSE(cast_ray(hf, pyr, {-5, 7, 10 + dz}, {1, 0.3, 0}).has_value()) << dz;
}

// Near-horizontal rays (elevation 1e-4..1e-2 rad, both up and down) aimed
// to pass just over or under random vertices (ridge points).
TEST(RayCast, GrazingRaysOverRidges) {
  const Heightfield hf = random_hf(65, 47, 10.0, 10.0, 4);
  const HeightPyramid pyr(hf);
  Uniform01 u01(21);
  Stats st, st_dda;
  for (int k = 0; k < 2000; ++k) {
    // Prefer local maxima: best of a few random vertices in a neighbourhood.
    int vi = 1 + int(u01() * (hf.width - 2)), vj = 1 + int(u01() * (hf.height - 2));
    for (int m = 0; m < 8; ++m) {
      const int ni = std::clamp(vi + int(u01() * 5) - 2, 0, hf.width - 1);
      const int nj = std::clamp(vj + int(u01() * 5) - 2, 0, hf.height - 1);
      if (hf.at(ni, nj) > hf.at(vi, vj)) vi = ni, vj = nj;
    }
    const dvec3 v{vi * hf.spacing_x_m, vj * hf.spacing_y_m, hf.at(vi, vj)};
    const double elev = std::exp(std::log(1e-4) + (std::log(1e-2) - std::log(1e-4)) * u01()) *
                        (u01() < 0.5 ? -1 : 1);
    const double az = 2 * M_PI * u01();
    const dvec3 d{std::cos(az) * std::cos(elev), std::sin(az) * std::cos(elev), std::sin(elev)};
    const double offset = std::exp(std::log(1e-7) + (std::log(1.0) - std::log(1e-7)) * u01()) *
                          (u01() < 0.5 ? -1 : 1);
    const dvec3 o = v - (50 + 400 * u01()) * d + dvec3{0, 0, offset};
    const RefHit ref = brute_force(hf, o, d);
    check_ray(hf, ref, cast_ray(hf, pyr, o, d), o, d, st, "grazing");
    check_ray(hf, ref, cast_ray_dda(hf, o, d), o, d, st_dda, "grazing (dda)");
  }
  expect_clean(st, "grazing", 2);
  expect_clean(st_dda, "grazing (dda)", 2);
}

// Heights on an exact plane z = a x + b y (representable floats), rays
// parallel to it and nearly parallel, offset by tiny amounts above/below.
void tilted_plane(double sx, double sy) {
  SCOPED_TRACE(testing::Message() << "spacing " << sx << "x" << sy);
  const Heightfield hf = make_hf(65, 65, sx, sy, [](int i, int j) { return float(0.5 * i + 0.25 * j); });
  const HeightPyramid pyr(hf);
  const LD a = LD(0.5) / sx, b = LD(0.25) / sy;  // dz/dx, dz/dy
  Uniform01 u01(31);
  const double ex = hf.extent_x_m(), ey = hf.extent_y_m();
  Stats st;
  int hits = 0;
  for (int k = 0; k < 1200; ++k) {
    const double az = 2 * M_PI * u01();
    const double dx = std::cos(az), dy = std::sin(az);
    const double dz_par = double(a * dx + b * dy);  // exactly along the plane (to rounding)
    // Start at 10..90% of the footprint so hits are inside.
    const double x = ex * (0.1 + 0.8 * u01()), y = ey * (0.1 + 0.8 * u01());
    const double surf = double(a * x + b * y);
    // Parallel rays: offsets 1e-9..1e-2 m. Near-parallel rays: angle to the
    // plane eps = 1e-8..1e-2 rad, offset = eps * (1..20 m). The hit t of a ray
    // at angle eps to a surface is only defined to ~1e-16 / eps relative in
    // double (normalising dir alone perturbs it that much), so smaller angles
    // cannot meet a 1e-6 tolerance.
    const double t_want = 1 + 19 * u01();
    const double eps = std::exp(std::log(1e-8) + (std::log(1e-2) - std::log(1e-8)) * u01());
    const double offset = (k % 2 == 0 ? std::exp(std::log(1e-9) + (std::log(1e-2) - std::log(1e-9)) * u01())
                                      : eps * t_want) *
                          (u01() < 0.5 ? -1 : 1);
    const dvec3 o{x, y, surf + offset};
    // f(p) = a x + b y - z: positive below the plane.
    const LD f_o = a * LD(o.x) + b * LD(o.y) - LD(o.z);
    if (k % 2 == 0) {
      // Parallel (to rounding of dz_par): offset >> rounding, so never hits.
      const dvec3 d{dx, dy, dz_par};
      const auto h = cast_ray(hf, pyr, o, d);
      EXPECT_FALSE(h.has_value()) << "parallel offset " << offset << " t=" << (h ? h->t : 0);
      check_ray(hf, brute_force(hf, o, d), h, o, d, st, "tilted parallel");
    } else {
      // Tilted towards the plane by eps so it hits after ~|offset|/eps metres.
      const dvec3 d{dx, dy, dz_par - (offset > 0 ? eps : -eps)};
      const LD len = std::sqrt(LD(d.x) * d.x + LD(d.y) * d.y + LD(d.z) * d.z);
      const LD rate = (a * d.x + b * d.y - d.z) / len;  // df/dt
      const double t_exact = double(-f_o / rate);
      const auto h = cast_ray(hf, pyr, o, d);
      check_ray(hf, brute_force(hf, o, d), h, o, d, st, "tilted near-parallel");
      const dvec3 p = o + t_exact * glm::normalize(d);
      const double margin = std::min(p.x, std::min(ex - p.x, std::min(p.y, ey - p.y)));
      if (t_exact > 0 && margin > 1e-6) {
        ASSERT_TRUE(h.has_value()) << "offset " << offset << " eps " << eps << " t_exact " << t_exact;
        ++hits;
        EXPECT_NEAR(h->t, t_exact, 1e-6 * t_exact) << "offset " << offset << " eps " << eps;
      } else if (margin < -1e-6) {
        EXPECT_FALSE(h.has_value()) << "crossing outside the footprint, t_exact " << t_exact;
      }
    }
  }
  EXPECT_GT(hits, 350);
  expect_clean(st, "tilted plane");
}

TEST(RayCast, RaysNearlyParallelToSlope) {
  tilted_plane(1.0, 1.0);
  tilted_plane(3.0, 0.7);
}

TEST(RayCast, VerticalRaysOnCornersAndEdges) {
  const Heightfield hf = random_hf(17, 12, 7.0, 4.5, 5);
  const HeightPyramid pyr(hf);
  const double top = hf.max_m + 10, bottom = hf.min_m - 10;
  for (int j = 0; j < hf.height; ++j)
    for (int i = 0; i < hf.width; ++i) {
      const double x = i * hf.spacing_x_m, y = j * hf.spacing_y_m, h = hf.at(i, j);
      auto down = cast_ray(hf, pyr, {x, y, top}, {0, 0, -3});  // not normalised
      ASSERT_TRUE(down.has_value()) << i << "," << j;
      EXPECT_NEAR(down->t, top - h, 1e-9);
      EXPECT_NEAR(down->point.z, h, 1e-9);
      auto up = cast_ray(hf, pyr, {x, y, bottom}, {0, 0, 1});
      ASSERT_TRUE(up.has_value()) << i << "," << j;
      EXPECT_NEAR(up->t, h - bottom, 1e-9);
      EXPECT_FALSE(cast_ray(hf, pyr, {x, y, top}, {0, 0, 1}).has_value());
      EXPECT_FALSE(cast_ray(hf, pyr, {x, y, bottom}, {0, 0, -1}).has_value());
      auto dda = cast_ray_dda(hf, {x, y, top}, {0, 0, -1});
      ASSERT_TRUE(dda.has_value());
      EXPECT_NEAR(dda->t, top - h, 1e-9);
      // Edge midpoints (east and north) and the cell diagonal's midpoint.
      for (auto [fx, fy] : {std::pair{0.5, 0.0}, {0.0, 0.5}, {0.5, 0.5}, {0.25, 0.75}}) {
        const double px = (i + fx) * hf.spacing_x_m, py = (j + fy) * hf.spacing_y_m;
        if (px > hf.extent_x_m() || py > hf.extent_y_m()) continue;
        const double want = hf.sample_surface(px, py);
        auto hd = cast_ray(hf, pyr, {px, py, top}, {0, 0, -1});
        ASSERT_TRUE(hd.has_value()) << px << "," << py;
        EXPECT_NEAR(hd->point.z, want, 1e-9);
        auto hu = cast_ray(hf, pyr, {px, py, bottom}, {0, 0, 1});
        ASSERT_TRUE(hu.has_value());
        EXPECT_NEAR(hu->point.z, want, 1e-9);
        auto hdda = cast_ray_dda(hf, {px, py, top}, {0, 0, -1});
        ASSERT_TRUE(hdda.has_value());
        EXPECT_NEAR(hdda->point.z, want, 1e-9);
      }
    }
  // Footprint boundary: on it hits, just outside misses.
  EXPECT_TRUE(cast_ray(hf, pyr, {0, 10, top}, {0, 0, -1}).has_value());
  EXPECT_TRUE(cast_ray(hf, pyr, {hf.extent_x_m(), hf.extent_y_m(), top}, {0, 0, -1}).has_value());
  EXPECT_FALSE(cast_ray(hf, pyr, {-1e-6, 10, top}, {0, 0, -1}).has_value());
  EXPECT_FALSE(cast_ray(hf, pyr, {10, hf.extent_y_m() + 1e-6, top}, {0, 0, -1}).has_value());
  EXPECT_FALSE(cast_ray_dda(hf, {-1e-6, 10, top}, {0, 0, -1}).has_value());
}

}  // namespace
