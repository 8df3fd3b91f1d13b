// BandRing::may_reach (lod/band_ring.h) must be conservative: wherever the
// inline band's search in shaders/level0_blend.frag could reach the grown
// square from a fragment of a piece, the piece must be said to reach it, or
// the piece is drawn without the band and the picture changes. Checked
// against that search's own arithmetic, in double, at random points of
// random pieces, flat and curved; and it must also leave far pieces out,
// or it buys nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "lod/band_ring.h"

namespace {

using ig::lod::BandRing;

// The shader's test: the ray window's two ends, in samples, against the
// square; true when the search may go on (not the early "own").
bool search_reaches(const BandRing& ring, const glm::dvec3& p) {
  const double t_own = glm::length(p - ring.eye);
  const glm::dvec3 dir = (p - ring.eye) / t_own;
  const double win = ring.tolerance_m + BandRing::kWindowPerMetre * t_own;
  const double t_lo = std::max(t_own - win, 0.0), t_hi = t_own + win;
  const glm::dvec2 eye_s = glm::dvec2(ring.eye) / ring.spacing;
  const glm::dvec2 a = eye_s + t_lo * glm::dvec2(dir) / ring.spacing, b = eye_s + t_hi * glm::dvec2(dir) / ring.spacing;
  const glm::dvec2 mn = glm::min(a, b), mx = glm::max(a, b);
  return !(mn.x > ring.hi.x || mn.y > ring.hi.y || mx.x < ring.lo.x || mx.y < ring.lo.y);
}

TEST(BandRing, EveryPieceTheSearchCanReachIsKept) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  long long reached = 0, kept = 0, left_out = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    BandRing ring;
    ring.spacing = {30.0, 25.0};
    ring.earth_radius_m = trial % 2 ? 6371000.0 : 0.0;
    const glm::ivec2 centre(int(200 + 3600 * u(rng)), int(200 + 3600 * u(rng)));
    const int half = int(16 + 300 * u(rng));
    ring.lo = centre - half;
    ring.hi = centre + half;
    ring.tolerance_m = 200.0 * u(rng);
    ring.eye = {4000 * 30.0 * u(rng), 4000 * 25.0 * u(rng), 500.0 + 3000.0 * u(rng)};
    const glm::ivec2 lo(int(4000 * u(rng)), int(4000 * u(rng)));
    const glm::ivec2 hi = lo + glm::ivec2(int(1 + 60 * u(rng)), int(1 + 60 * u(rng)));
    const double z_lo = 3000.0 * u(rng), z_hi = z_lo + 500.0 * u(rng);
    const bool may = ring.may_reach(lo, hi, z_lo, z_hi);
    (may ? kept : left_out) += 1;
    for (int k = 0; k < 64; ++k) {
      glm::dvec3 p(glm::mix(double(lo.x), double(hi.x), u(rng)) * ring.spacing.x,
                   glm::mix(double(lo.y), double(hi.y), u(rng)) * ring.spacing.y, glm::mix(z_lo, z_hi, u(rng)));
      if (ring.earth_radius_m > 0.0) {  // drawn dropped by the curvature, as the vertex shader does
        const double d2 = glm::dot(glm::dvec2(p - ring.eye), glm::dvec2(p - ring.eye));
        p.z -= d2 / (ring.earth_radius_m + std::sqrt(ring.earth_radius_m * ring.earth_radius_m - d2));
      }
      if (!search_reaches(ring, p)) continue;
      ++reached;
      ASSERT_TRUE(may) << "trial " << trial << ": piece [" << lo.x << "," << lo.y << "]-[" << hi.x << "," << hi.y
                       << "] reached at (" << p.x << ", " << p.y << ", " << p.z << ") but left out";
    }
  }
  std::printf("pieces kept %lld, left out %lld; points whose search reached the square %lld\n", kept, left_out,
              reached);
  EXPECT_GT(reached, 0);
  EXPECT_GT(left_out, kept) << "most random pieces lie far from a random square";
}

TEST(BandRing, NearPiecesKeptFarPiecesLeftOutNoBandNothing) {
  BandRing ring;
  ring.spacing = {30.0, 30.0};
  ring.lo = {1000, 1000};
  ring.hi = {1300, 1300};
  ring.eye = {900 * 30.0, 900 * 30.0, 2500.0};
  ring.tolerance_m = 60.0;
  EXPECT_TRUE(ring.may_reach({1290, 1290}, {1310, 1310}, 1000.0, 1200.0)) << "across the square's edge";
  EXPECT_TRUE(ring.may_reach({1305, 1100}, {1320, 1120}, 1000.0, 1200.0)) << "just outside, within the window";
  EXPECT_FALSE(ring.may_reach({3000, 3000}, {3020, 3020}, 1000.0, 1200.0)) << "kilometres beyond the window";
  EXPECT_FALSE(ring.may_reach({100, 1100}, {120, 1120}, 1000.0, 1200.0)) << "behind the eye, far from the square";
  ring.hi = {999, 999};  // no band
  EXPECT_FALSE(ring.may_reach({1290, 1290}, {1310, 1310}, 1000.0, 1200.0));
}

}  // namespace
