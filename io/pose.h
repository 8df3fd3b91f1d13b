#pragma once
// Ownship / eye pose and the attitude convention used across the IG.
//
// World frame: terrain-local ENU (x east, y north, z up), metres, double.
// Body frame: x right, y forward, z up; identity attitude looks north, level.
// Heading 0 = north, clockwise positive; pitch nose-up positive; roll right
// wing down positive. attitude = Rz(-heading) * Rx(pitch) * Ry(roll), a
// rotation body -> world.

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

namespace ig::io {

struct Hpr {
  double heading_deg = 0.0;  // [0, 360)
  double pitch_deg = 0.0;    // [-90, 90]
  double roll_deg = 0.0;     // (-180, 180]
};

struct Pose {
  glm::dvec3 position{0.0};
  glm::dquat attitude{1.0, 0.0, 0.0, 0.0};  // body -> world (w, x, y, z)
};

glm::dquat attitude_from_hpr(const Hpr& hpr);
// Inverse of attitude_from_hpr; at pitch +-90 the heading/roll split is
// resolved by putting all of it into heading (roll = 0).
Hpr hpr_from_attitude(const glm::dquat& q);

// Combine a channel's view offset (heading/pitch/roll relative to the body).
glm::dquat apply_view_offset(const glm::dquat& body, const Hpr& offset);

// Body axes in world coordinates.
glm::dvec3 forward_of(const glm::dquat& q);  // body +y
glm::dvec3 right_of(const glm::dquat& q);    // body +x
glm::dvec3 up_of(const glm::dquat& q);       // body +z

}  // namespace ig::io
