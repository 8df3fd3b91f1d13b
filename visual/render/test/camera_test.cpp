// Camera conventions, reversed-Z projection and frustum culling (math only).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_access.hpp>

#include "io/pose.h"
#include "render/camera.h"

namespace {

using ig::render::Camera;

Camera camera_at(double heading, double pitch, double roll) {
  Camera c;
  c.attitude = ig::io::attitude_from_hpr({heading, pitch, roll});
  c.near_m = 0.5;
  c.far_m = 300000.0;
  c.fov_y_deg = 60.0;
  c.aspect = 4.0 / 3.0;
  return c;
}

void expect_vec(const glm::dvec3& a, const glm::dvec3& b) {
  EXPECT_NEAR(a.x, b.x, 1e-9);
  EXPECT_NEAR(a.y, b.y, 1e-9);
  EXPECT_NEAR(a.z, b.z, 1e-9);
}

TEST(Camera, HeadingZeroLooksNorthNinetyLooksEast) {
  expect_vec(camera_at(0, 0, 0).forward(), {0, 1, 0});
  expect_vec(camera_at(90, 0, 0).forward(), {1, 0, 0});
  expect_vec(camera_at(180, 0, 0).forward(), {0, -1, 0});
  expect_vec(camera_at(270, 0, 0).forward(), {-1, 0, 0});
}

TEST(Camera, PitchUpPositiveRollRightWingDownPositive) {
  EXPECT_NEAR(camera_at(0, 30, 0).forward().z, 0.5, 1e-12);
  EXPECT_NEAR(camera_at(0, -90, 0).forward().z, -1.0, 1e-12);
  const Camera rolled = camera_at(0, 0, 20);
  EXPECT_LT(rolled.right().z, 0.0) << "right wing goes down";
  EXPECT_GT(rolled.up().x, 0.0) << "the view's up tilts to the right";
}

TEST(Camera, ReversedZMapsNearToOneAndFarToZero) {
  const Camera c = camera_at(0, 0, 0);
  const glm::mat4 vp = c.view_projection();
  auto depth_of = [&](double d) {
    const glm::vec4 clip = vp * glm::vec4(0.f, float(d), 0.f, 1.f);  // d metres ahead (north)
    return double(clip.z / clip.w);
  };
  EXPECT_NEAR(depth_of(c.near_m), 1.0, 1e-6);
  EXPECT_NEAR(depth_of(c.far_m), 0.0, 1e-6);
  EXPECT_GT(depth_of(1000.0), depth_of(1001.0)) << "nearer is greater";
  for (double d : {1.0, 100.0, 5000.0, 100000.0})
    EXPECT_NEAR(c.depth_to_view_distance(float(depth_of(d))), d, d * 1e-5);
}

TEST(Camera, CentrePixelRayIsTheForwardAxis) {
  const Camera c = camera_at(33, -12, 7);
  const glm::dvec3 r = c.pixel_ray(319.5, 239.5, 640, 480);
  EXPECT_NEAR(glm::dot(r, c.forward()), 1.0, 1e-12);
  // Top-left pixel ray leans up and left.
  const glm::dvec3 tl = c.pixel_ray(0, 0, 640, 480);
  EXPECT_GT(glm::dot(tl, c.up()), 0.0);
  EXPECT_LT(glm::dot(tl, c.right()), 0.0);
}

TEST(Camera, FrustumKeepsBoxesAheadAndCullsBoxesBehind) {
  const Camera c = camera_at(0, 0, 0);
  const auto f = ig::render::frustum_of(c);
  EXPECT_TRUE(f.intersects_box({-10, 100, -10}, {10, 120, 10}));
  EXPECT_FALSE(f.intersects_box({-10, -120, -10}, {10, -100, 10})) << "behind";
  EXPECT_FALSE(f.intersects_box({-10, 400000, -10}, {10, 400100, 10})) << "past far";
  EXPECT_FALSE(f.intersects_box({5000, 100, -10}, {5100, 120, 10})) << "far right of a 60 deg view";
  EXPECT_TRUE(f.intersects_box({-1e6, -1e6, -5}, {1e6, 1e6, 5})) << "a box around the eye";
}

}  // namespace
