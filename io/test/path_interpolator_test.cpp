#include "io/path_interpolator.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

namespace {

using namespace ig::io;

PathKey key(double t, double x, double y, double z, double h = 0, double p = 0, double r = 0) {
  return PathKey{t, {x, y, z}, h, p, r};
}

PathSpec path_of(std::initializer_list<PathKey> keys) {
  PathSpec p;
  p.keys.assign(keys.begin(), keys.end());
  return p;
}

bool finite(const Pose& p) {
  return std::isfinite(p.position.x) && std::isfinite(p.position.y) && std::isfinite(p.position.z) &&
         std::isfinite(p.attitude.w) && std::isfinite(p.attitude.x) && std::isfinite(p.attitude.y) &&
         std::isfinite(p.attitude.z);
}

// Angle between two rotations, degrees (atan2 form: accurate for tiny angles,
// where acos of a dot product near 1 is not).
double rotation_angle_deg(const glm::dquat& a, const glm::dquat& b) {
  const glm::dquat d = glm::conjugate(glm::normalize(a)) * glm::normalize(b);
  const double v = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  return 2.0 * std::atan2(v, std::fabs(d.w)) * 180.0 / 3.14159265358979323846;
}

double heading_delta(double a, double b) { return std::fabs(std::remainder(a - b, 360.0)); }

PathSpec uneven_path() {
  return path_of({key(0.0, 0, 0, 100, 0, 0, 0), key(0.7, 50, 10, 120, 20, 5, 10), key(3.0, 200, 150, 90, 80, -5, 30),
                  key(3.4, 230, 170, 95, 90, 0, 0), key(8.0, 600, 100, 300, 180, 10, -20)});
}

TEST(PathInterpolator, PassesThroughEveryKey) {
  const PathSpec spec = uneven_path();
  const PathInterpolator interp(spec);
  for (const PathKey& k : spec.keys) {
    const Pose p = interp.sample(k.t_s);
    EXPECT_NEAR(p.position.x, k.position[0], 1e-9);
    EXPECT_NEAR(p.position.y, k.position[1], 1e-9);
    EXPECT_NEAR(p.position.z, k.position[2], 1e-9);
    EXPECT_LT(rotation_angle_deg(p.attitude, ig::io::attitude_from_hpr({k.heading_deg, k.pitch_deg, k.roll_deg})),
              1e-6);
  }
  EXPECT_DOUBLE_EQ(interp.first_time_s(), 0.0);
  EXPECT_DOUBLE_EQ(interp.last_time_s(), 8.0);
}

TEST(PathInterpolator, VelocityContinuousAtInteriorKeys) {
  const PathSpec spec = uneven_path();
  const PathInterpolator interp(spec);
  const double e = 1e-5;
  for (std::size_t i = 1; i + 1 < spec.keys.size(); ++i) {
    const double t = spec.keys[i].t_s;
    // One-sided finite differences from the left and the right segments.
    const glm::dvec3 vl = (interp.sample(t).position - interp.sample(t - e).position) / e;
    const glm::dvec3 vr = (interp.sample(t + e).position - interp.sample(t).position) / e;
    const double scale = std::max(1.0, glm::length(vl));
    EXPECT_LT(glm::length(vl - vr) / scale, 1e-3) << "key " << i;
  }
  // Far from keys, neighbouring samples never jump.
  glm::dvec3 prev = interp.sample(0.0).position;
  for (int k = 1; k <= 8000; ++k) {
    const glm::dvec3 cur = interp.sample(k * 1e-3).position;
    EXPECT_LT(glm::length(cur - prev), 2.0);
    prev = cur;
  }
}

TEST(PathInterpolator, LinearMotionStaysLinearWithUnevenKeys) {
  // Keys on a straight line at constant speed but uneven times: the
  // non-uniform tangents reproduce the motion exactly (no overshoot).
  const PathInterpolator interp(
      path_of({key(0, 0, 0, 0), key(0.5, 5, 10, 1), key(3, 30, 60, 6), key(3.2, 32, 64, 6.4), key(10, 100, 200, 20)}));
  for (double t = 0.0; t <= 10.0; t += 0.037) {
    const Pose p = interp.sample(t);
    EXPECT_NEAR(p.position.x, 10.0 * t, 1e-9);
    EXPECT_NEAR(p.position.y, 20.0 * t, 1e-9);
    EXPECT_NEAR(p.position.z, 2.0 * t, 1e-9);
  }
}

TEST(PathInterpolator, QuadraticMotionReproducedAtInteriorKeys) {
  // x = t^2: the interior tangents (three-point parabola) equal 2t exactly.
  const PathInterpolator interp(
      path_of({key(0, 0, 0, 0), key(1, 1, 0, 0), key(1.5, 2.25, 0, 0), key(4, 16, 0, 0), key(5, 25, 0, 0)}));
  const double e = 1e-6;
  for (double t : {1.0, 1.5, 4.0}) {
    const double v = (interp.sample(t + e).position.x - interp.sample(t - e).position.x) / (2 * e);
    EXPECT_NEAR(v, 2.0 * t, 1e-4);
  }
}

TEST(PathInterpolator, HeadingWrapsTheShortWay) {
  const PathInterpolator interp(path_of({key(0, 0, 0, 0, 350, 0, 0), key(1, 0, 0, 0, 10, 0, 0)}));
  const Hpr mid = ig::io::hpr_from_attitude(interp.sample(0.5).attitude);
  EXPECT_LT(heading_delta(mid.heading_deg, 0.0), 1e-9);
  EXPECT_NEAR(mid.pitch_deg, 0.0, 1e-9);
  EXPECT_NEAR(mid.roll_deg, 0.0, 1e-9);
  for (double t = 0.0; t <= 1.0; t += 0.01) {
    const Hpr h = ig::io::hpr_from_attitude(interp.sample(t).attitude);
    // Stays within the 20 degree arc through north, never near 180.
    EXPECT_LE(heading_delta(h.heading_deg, 0.0), 10.0 + 1e-9) << t;
  }
  // Quarter way: 355 degrees, i.e. linear in angle.
  const Hpr q = ig::io::hpr_from_attitude(interp.sample(0.25).attitude);
  EXPECT_LT(heading_delta(q.heading_deg, 355.0), 1e-9);
}

TEST(PathInterpolator, HeadingDecreasingAcrossNorth) {
  const PathInterpolator interp(path_of({key(0, 0, 0, 0, 5, 0, 0), key(2, 0, 0, 0, -25, 0, 0)}));
  const Hpr mid = ig::io::hpr_from_attitude(interp.sample(1.0).attitude);
  EXPECT_LT(heading_delta(mid.heading_deg, 350.0), 1e-9);
}

TEST(PathInterpolator, ThroughThePolesNoNaN) {
  // Pull up through the vertical: pitch 60 heading 0 -> pitch 60 heading 180
  // (over the top), and a dive straight down then back.
  const PathInterpolator loop(path_of({key(0, 0, 0, 0, 0, 60, 0), key(1, 0, 0, 0, 0, 90, 0),
                                       key(2, 0, 0, 0, 180, 60, 180), key(3, 0, 0, 0, 0, -90, 0),
                                       key(4, 0, 0, 0, 45, -80, 10)}));
  for (double t = -1.0; t <= 5.0; t += 0.001) {
    const Pose p = loop.sample(t);
    ASSERT_TRUE(finite(p)) << t;
    const Hpr h = ig::io::hpr_from_attitude(p.attitude);
    ASSERT_FALSE(std::isnan(h.heading_deg) || std::isnan(h.pitch_deg) || std::isnan(h.roll_deg)) << t;
    EXPECT_NEAR(glm::length(p.attitude), 1.0, 1e-12);
  }
  // Half way between pitch 60 and pitch 90 (same heading) is pitch 75.
  EXPECT_NEAR(ig::io::hpr_from_attitude(loop.sample(0.5).attitude).pitch_deg, 75.0, 1e-9);
  // pitch 60 hdg 0 -> pitch 60 hdg 180 roll 180 is a 60 degree pitch-up over the top.
  EXPECT_NEAR(rotation_angle_deg(loop.sample(1.0).attitude, loop.sample(2.0).attitude), 30.0, 1e-9);
}

TEST(PathInterpolator, IdenticalAndNearlyIdenticalAttitudes) {
  const PathInterpolator same(path_of({key(0, 0, 0, 0, 10, 5, 3), key(1, 10, 0, 0, 10, 5, 3)}));
  const PathInterpolator close(path_of({key(0, 0, 0, 0, 10, 5, 3), key(1, 10, 0, 0, 10 + 1e-10, 5, 3)}));
  for (double t = 0.0; t <= 1.0; t += 0.05) {
    ASSERT_TRUE(finite(same.sample(t)));
    ASSERT_TRUE(finite(close.sample(t)));
    EXPECT_LT(rotation_angle_deg(same.sample(t).attitude, ig::io::attitude_from_hpr({10, 5, 3})), 1e-6);
  }
}

TEST(PathInterpolator, SingleKeyIsConstant) {
  const PathInterpolator interp(path_of({key(2.0, 1, 2, 3, 45, 10, -5)}));
  for (double t : {-100.0, 0.0, 2.0, 3.0, 1e9}) {
    const Pose p = interp.sample(t);
    EXPECT_EQ(p.position, glm::dvec3(1, 2, 3));
    EXPECT_LT(rotation_angle_deg(p.attitude, ig::io::attitude_from_hpr({45, 10, -5})), 1e-9);
  }
}

TEST(PathInterpolator, ClampsOutsideKeyRange) {
  const PathInterpolator interp(path_of({key(1, 0, 0, 10, 0, 0, 0), key(2, 100, 0, 10, 90, 0, 0)}));
  EXPECT_EQ(interp.sample(0.0).position, glm::dvec3(0, 0, 10));
  EXPECT_EQ(interp.sample(-1e300).position, glm::dvec3(0, 0, 10));
  EXPECT_EQ(interp.sample(2.5).position, glm::dvec3(100, 0, 10));
  EXPECT_EQ(interp.sample(1e300).position, glm::dvec3(100, 0, 10));
  EXPECT_NEAR(ig::io::hpr_from_attitude(interp.sample(50).attitude).heading_deg, 90.0, 1e-9);
  EXPECT_TRUE(finite(interp.sample(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_TRUE(finite(interp.sample(std::numeric_limits<double>::infinity())));
}

TEST(PathInterpolator, RejectsBadPaths) {
  EXPECT_THROW(PathInterpolator(PathSpec{}), std::invalid_argument);
  EXPECT_THROW(PathInterpolator(path_of({key(1, 0, 0, 0), key(1, 1, 0, 0)})), std::invalid_argument);
  EXPECT_THROW(PathInterpolator(path_of({key(2, 0, 0, 0), key(1, 1, 0, 0)})), std::invalid_argument);
}

TEST(PathInterpolator, Deterministic) {
  const PathInterpolator a(uneven_path());
  const PathInterpolator b(uneven_path());
  for (int k = 0; k < 500; ++k) {
    const double t = k / 60.0;
    const Pose pa = a.sample(t);
    const Pose pb = b.sample(t);
    EXPECT_EQ(pa.position, pb.position);
    EXPECT_EQ(pa.attitude, pb.attitude);
  }
}

}  // namespace
