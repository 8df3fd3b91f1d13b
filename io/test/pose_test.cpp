#include "io/pose.h"

#include <cmath>

#include <gtest/gtest.h>

namespace {

using namespace ig::io;

constexpr double kPi = 3.14159265358979323846;
double rad(double deg) { return deg * kPi / 180.0; }

void expect_vec(const glm::dvec3& got, const glm::dvec3& want, double tol = 1e-12) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

// Same rotation: compare the three body axes in world.
void expect_same_rotation(const glm::dquat& a, const glm::dquat& b, double tol = 1e-9) {
  expect_vec(forward_of(a), forward_of(b), tol);
  expect_vec(right_of(a), right_of(b), tol);
  expect_vec(up_of(a), up_of(b), tol);
}

TEST(Pose, IdentityLooksNorthLevel) {
  const glm::dquat q = attitude_from_hpr({0, 0, 0});
  expect_vec(forward_of(q), {0, 1, 0});
  expect_vec(right_of(q), {1, 0, 0});
  expect_vec(up_of(q), {0, 0, 1});
}

TEST(Pose, Heading90LooksEast) {
  const glm::dquat q = attitude_from_hpr({90, 0, 0});
  expect_vec(forward_of(q), {1, 0, 0});
  expect_vec(right_of(q), {0, -1, 0});  // right wing points south
  expect_vec(up_of(q), {0, 0, 1});
}

TEST(Pose, HeadingIsClockwiseFromNorth) {
  expect_vec(forward_of(attitude_from_hpr({180, 0, 0})), {0, -1, 0});
  expect_vec(forward_of(attitude_from_hpr({270, 0, 0})), {-1, 0, 0});
  expect_vec(forward_of(attitude_from_hpr({45, 0, 0})), {std::sqrt(0.5), std::sqrt(0.5), 0});
}

TEST(Pose, PitchUpRaisesNose) {
  const glm::dquat q = attitude_from_hpr({0, 30, 0});
  expect_vec(forward_of(q), {0, std::cos(rad(30)), std::sin(rad(30))});
  EXPECT_NEAR(forward_of(q).z, 0.5, 1e-12);
  // With a heading, pitch still raises the nose.
  const glm::dquat q2 = attitude_from_hpr({90, 30, 0});
  expect_vec(forward_of(q2), {std::cos(rad(30)), 0, 0.5});
}

TEST(Pose, RollRightPutsRightWingDown) {
  const glm::dquat q = attitude_from_hpr({0, 0, 20});
  EXPECT_LT(right_of(q).z, 0.0);
  expect_vec(right_of(q), {std::cos(rad(20)), 0, -std::sin(rad(20))});
  expect_vec(forward_of(q), {0, 1, 0});  // roll is about the forward axis
  EXPECT_GT(up_of(q).x, 0.0);           // top of the aircraft leans right (east)
}

TEST(Pose, ConventionOrderHeadingPitchRoll) {
  // Roll is applied in the body (innermost), heading in the world (outermost):
  // with heading 90 and roll 20 the right wing points south and down.
  const glm::dquat q = attitude_from_hpr({90, 10, 20});
  const glm::dvec3 f = forward_of(q);
  EXPECT_NEAR(f.z, std::sin(rad(10)), 1e-12);
  EXPECT_NEAR(f.x, std::cos(rad(10)), 1e-12);
  const glm::dvec3 r = right_of(q);
  EXPECT_LT(r.y, 0.0);
  EXPECT_LT(r.z, 0.0);
  // Axes stay orthonormal and right-handed: right x forward = up.
  expect_vec(glm::cross(right_of(q), forward_of(q)), up_of(q));
}

TEST(Pose, RoundTripGrid) {
  int checked = 0;
  for (double h = -360.0; h <= 720.0; h += 22.5) {
    for (double p = -90.0; p <= 90.0; p += 7.5) {
      for (double r = -180.0; r <= 180.0; r += 15.0) {
        const glm::dquat q = attitude_from_hpr({h, p, r});
        const Hpr back = hpr_from_attitude(q);
        ASSERT_TRUE(std::isfinite(back.heading_deg) && std::isfinite(back.pitch_deg) && std::isfinite(back.roll_deg))
            << h << " " << p << " " << r;
        EXPECT_GE(back.heading_deg, 0.0);
        EXPECT_LT(back.heading_deg, 360.0);
        EXPECT_GE(back.pitch_deg, -90.0);
        EXPECT_LE(back.pitch_deg, 90.0);
        EXPECT_GT(back.roll_deg, -180.0);
        EXPECT_LE(back.roll_deg, 180.0);
        // Whatever the split, it is the same rotation.
        expect_same_rotation(attitude_from_hpr(back), q, 1e-9);
        if (std::fabs(p) < 90.0) {
          EXPECT_NEAR(back.pitch_deg, p, 1e-9);
          // Heading and roll come back modulo 360.
          const double dh = std::remainder(back.heading_deg - h, 360.0);
          const double dr = std::remainder(back.roll_deg - r, 360.0);
          EXPECT_NEAR(dh, 0.0, 1e-8) << h << " " << p << " " << r;
          EXPECT_NEAR(dr, 0.0, 1e-8) << h << " " << p << " " << r;
        } else {
          EXPECT_EQ(back.pitch_deg, p);
          EXPECT_EQ(back.roll_deg, 0.0);  // all of it in heading at the poles
        }
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 10000);
}

TEST(Pose, NearPolesNoNaN) {
  for (double p : {89.9999999, 89.99999999999, 90.0, -90.0, -89.9999999, 90.0 - 1e-14}) {
    for (double h : {0.0, 33.0, 179.0, 359.9}) {
      for (double r : {0.0, 45.0, -170.0}) {
        const glm::dquat q = attitude_from_hpr({h, p, r});
        const Hpr back = hpr_from_attitude(q);
        ASSERT_FALSE(std::isnan(back.heading_deg) || std::isnan(back.pitch_deg) || std::isnan(back.roll_deg));
        EXPECT_NEAR(back.pitch_deg, p, 1e-6);
        expect_same_rotation(attitude_from_hpr(back), q, 1e-7);
      }
    }
  }
}

TEST(Pose, PoleSplitPutsEverythingInHeading) {
  // Looking straight up with heading 30 and roll 20 is the same view as
  // heading 10 without roll (for pitch +90, heading - roll is what counts).
  const Hpr up = hpr_from_attitude(attitude_from_hpr({30, 90, 20}));
  EXPECT_DOUBLE_EQ(up.pitch_deg, 90.0);
  EXPECT_EQ(up.roll_deg, 0.0);
  EXPECT_NEAR(up.heading_deg, 10.0, 1e-9);
  const Hpr down = hpr_from_attitude(attitude_from_hpr({30, -90, 20}));
  EXPECT_DOUBLE_EQ(down.pitch_deg, -90.0);
  EXPECT_EQ(down.roll_deg, 0.0);
  EXPECT_NEAR(down.heading_deg, 50.0, 1e-9);
}

TEST(Pose, SlightlyDenormalisedQuaternionDoesNotNaN) {
  // A quaternion a hair longer than unit length would push asin past 1.
  glm::dquat q = attitude_from_hpr({0, 90, 0});
  q *= 1.0000001;
  const Hpr back = hpr_from_attitude(q);
  EXPECT_DOUBLE_EQ(back.pitch_deg, 90.0);
  EXPECT_FALSE(std::isnan(back.heading_deg));
  // Zero quaternion: no NaN either (treated as identity).
  const Hpr zero = hpr_from_attitude(glm::dquat(0, 0, 0, 0));
  EXPECT_FALSE(std::isnan(zero.heading_deg) || std::isnan(zero.pitch_deg) || std::isnan(zero.roll_deg));
}

TEST(Pose, HeadingWrapsIntoRange) {
  EXPECT_NEAR(hpr_from_attitude(attitude_from_hpr({-10, 0, 0})).heading_deg, 350.0, 1e-9);
  EXPECT_NEAR(hpr_from_attitude(attitude_from_hpr({370, 0, 0})).heading_deg, 10.0, 1e-9);
  const double h = hpr_from_attitude(attitude_from_hpr({-1e-15, 0, 0})).heading_deg;
  EXPECT_GE(h, 0.0);
  EXPECT_LT(h, 360.0);
  EXPECT_NEAR(hpr_from_attitude(attitude_from_hpr({0, 0, 180})).roll_deg, 180.0, 1e-9);
  EXPECT_NEAR(hpr_from_attitude(attitude_from_hpr({0, 0, -180})).roll_deg, 180.0, 1e-9);
}

TEST(Pose, ViewOffsetIsRelativeToBody) {
  // Aircraft heading 90 (east), left channel looking 60 deg left: north-east.
  const glm::dquat body = attitude_from_hpr({90, 0, 0});
  const glm::dquat left = apply_view_offset(body, {-60, 0, 0});
  expect_vec(forward_of(left), {std::cos(rad(60)), std::sin(rad(60)), 0});
  // Offsets are in the body frame: with the aircraft rolled 90 deg right, a
  // channel pitched up 30 deg looks towards the right wing (and level).
  const glm::dquat rolled = attitude_from_hpr({0, 0, 90});
  const glm::dquat up30 = apply_view_offset(rolled, {0, 30, 0});
  const glm::dvec3 f = forward_of(up30);
  EXPECT_NEAR(f.z, 0.0, 1e-12);
  EXPECT_NEAR(f.x, 0.5, 1e-12);  // toward +x (east), where the raised "up" axis points
  // The zero offset changes nothing.
  expect_same_rotation(apply_view_offset(body, {0, 0, 0}), body, 1e-12);
  // Offset composition equals body * offset.
  const glm::dquat b = attitude_from_hpr({12, -5, 33});
  const glm::dquat o = attitude_from_hpr({-60, 4, 2});
  expect_same_rotation(apply_view_offset(b, {-60, 4, 2}), b * o, 1e-12);
}

}  // namespace
