#include "io/pose.h"

#include <algorithm>
#include <cmath>

#include <glm/mat3x3.hpp>

#include "io/wire/pose_message.h"

namespace ig::io {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegToRad = kPi / 180.0;
constexpr double kRadToDeg = 180.0 / kPi;

// Below this horizontal length of the forward axis the attitude is treated as
// looking straight up or down (gimbal lock): about 2e-6 degrees from the pole.
constexpr double kPoleEpsilon = 4e-8;

// Right-handed rotation by `angle_rad` about a principal axis.
glm::dquat axis_rotation(double angle_rad, int axis) {
  const double h = 0.5 * angle_rad;
  const double s = std::sin(h);
  glm::dquat q(std::cos(h), 0.0, 0.0, 0.0);
  if (axis == 0) q.x = s;
  if (axis == 1) q.y = s;
  if (axis == 2) q.z = s;
  return q;
}

}  // namespace

glm::dquat attitude_from_hpr(const Hpr& hpr) {
  // attitude = Rz(-heading) * Rx(pitch) * Ry(roll)
  const glm::dquat qz = axis_rotation(-hpr.heading_deg * kDegToRad, 2);
  const glm::dquat qx = axis_rotation(hpr.pitch_deg * kDegToRad, 0);
  const glm::dquat qy = axis_rotation(hpr.roll_deg * kDegToRad, 1);
  return glm::normalize(qz * qx * qy);
}

Hpr hpr_from_attitude(const glm::dquat& q_in) {
  const double len = glm::length(q_in);
  const glm::dquat q = (len > 0.0 && std::isfinite(len)) ? q_in / len : glm::dquat(1.0, 0.0, 0.0, 0.0);
  // glm matrices are column-major: m[col][row]. With M = Rz(-h) Rx(p) Ry(r):
  //   M[0][1] = sin h cos p   M[1][1] = cos h cos p   M[2][1] = sin p
  //   M[2][0] = -cos p sin r  M[2][2] = cos p cos r
  const glm::dmat3 m = glm::mat3_cast(q);
  const auto at = [&m](int row, int col) { return m[col][row]; };

  const double fx = at(0, 1);  // forward axis (body +y) in world
  const double fy = at(1, 1);
  const double fz = std::clamp(at(2, 1), -1.0, 1.0);
  const double horiz = std::sqrt(fx * fx + fy * fy);

  Hpr out;
  // atan2 of the two components is accurate everywhere, unlike asin near +-1.
  out.pitch_deg = std::clamp(std::atan2(fz, horiz) * kRadToDeg, -90.0, 90.0);
  if (horiz > kPoleEpsilon) {
    out.heading_deg = std::atan2(fx, fy) * kRadToDeg;
    out.roll_deg = std::atan2(-at(2, 0), at(2, 2)) * kRadToDeg;
  } else {
    // Looking straight up/down: heading and roll are the same rotation. Put it
    // all in heading. With roll = 0, M[0][0] = cos h and M[1][0] = -sin h.
    out.pitch_deg = fz > 0.0 ? 90.0 : -90.0;
    out.heading_deg = std::atan2(-at(1, 0), at(0, 0)) * kRadToDeg;
    out.roll_deg = 0.0;
  }
  out.heading_deg = wire::wrap_360(out.heading_deg);
  out.roll_deg = wire::wrap_180(out.roll_deg);
  return out;
}

glm::dquat apply_view_offset(const glm::dquat& body, const Hpr& offset) {
  return glm::normalize(body * attitude_from_hpr(offset));
}

glm::dvec3 forward_of(const glm::dquat& q) { return q * glm::dvec3(0.0, 1.0, 0.0); }
glm::dvec3 right_of(const glm::dquat& q) { return q * glm::dvec3(1.0, 0.0, 0.0); }
glm::dvec3 up_of(const glm::dquat& q) { return q * glm::dvec3(0.0, 0.0, 1.0); }

}  // namespace ig::io
