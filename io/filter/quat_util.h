#pragma once
// Small double-precision quaternion helpers shared by the pose filter and its
// tests: rotation vectors (axis * angle, radians) <-> unit quaternions, the
// short-arc slerp (GLM's), and the angle between two attitudes.

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

namespace ig::io::quat {

// Unit quaternion rotating by |v| radians about v / |v| (right-handed).
inline glm::dquat exp_rotvec(const glm::dvec3& v) {
  const double angle = glm::length(v);
  if (angle < 1e-12) return glm::normalize(glm::dquat(1.0, 0.5 * v.x, 0.5 * v.y, 0.5 * v.z));
  const double s = std::sin(0.5 * angle) / angle;
  return glm::dquat(std::cos(0.5 * angle), v.x * s, v.y * s, v.z * s);
}

// Rotation vector of a unit quaternion, angle in [0, pi] (short arc).
inline glm::dvec3 log_rotvec(glm::dquat q) {
  if (q.w < 0.0) q = -q;
  const double vn = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
  if (vn < 1e-12) return glm::dvec3(2.0 * q.x, 2.0 * q.y, 2.0 * q.z);
  const double angle = 2.0 * std::atan2(vn, q.w);
  return glm::dvec3(q.x, q.y, q.z) * (angle / vn);
}

// Spherical linear interpolation along the short arc (q and -q are the same
// rotation), f clamped to [0, 1]: GLM's slerp, which takes the short path and
// falls back to a linear blend where the two nearly coincide.
inline glm::dquat slerp_short(const glm::dquat& a, const glm::dquat& b, double f) {
  return glm::normalize(glm::slerp(a, b, std::clamp(f, 0.0, 1.0)));
}

// Angle in radians of the rotation taking a to b, in [0, pi].
// atan2 form: accurate for tiny angles too (acos of ~1 is not).
inline double angle_between(const glm::dquat& a, const glm::dquat& b) {
  const glm::dquat r = glm::conjugate(glm::normalize(a)) * glm::normalize(b);
  const double vn = std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
  return 2.0 * std::atan2(vn, std::fabs(r.w));
}

inline bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline bool finite(const glm::dquat& q) {
  return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

}  // namespace ig::io::quat
