#pragma once
// Smooth sampling of a scenario's keyframed path: position by cubic Hermite
// interpolation with Catmull-Rom style tangents that respect uneven key times
// (passes through every key, C1), attitude by quaternion slerp along the
// shortest arc (safe across 359 -> 1 deg and through the poles).
// Positions stay in the path's own frame (local metres or lat/lon/alt); the
// caller places them on the terrain.

#include <vector>

#include "io/pose.h"
#include "io/scenario.h"

namespace ig::io {

class PathInterpolator {
 public:
  // Throws std::invalid_argument when the path has no keys or its key times
  // are not finite and strictly increasing (parse_scenario already checks).
  explicit PathInterpolator(const PathSpec& path);
  // Before the first key: the first key; after the last: the last key.
  Pose sample(double t_s) const;

  double first_time_s() const { return times_.front(); }
  double last_time_s() const { return times_.back(); }

 private:
  std::vector<double> times_;
  std::vector<glm::dvec3> positions_;
  std::vector<glm::dquat> attitudes_;  // consecutive ones in the same hemisphere
  std::vector<glm::dvec3> tangents_;   // dp/dt at each key (per second)
};

}  // namespace ig::io
