#include "io/path_interpolator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "io/filter/quat_util.h"

namespace ig::io {
using quat::slerp_short;

PathInterpolator::PathInterpolator(const PathSpec& path) {
  if (path.keys.empty()) throw std::invalid_argument("PathInterpolator: path has no keys");
  const std::size_t n = path.keys.size();
  times_.reserve(n);
  positions_.reserve(n);
  attitudes_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const PathKey& k = path.keys[i];
    if (!std::isfinite(k.t_s)) {
      throw std::invalid_argument("PathInterpolator: key " + std::to_string(i) + " time is not finite");
    }
    if (i > 0 && !(k.t_s > times_.back())) {
      throw std::invalid_argument("PathInterpolator: key times must be strictly increasing (key " +
                                  std::to_string(i) + ")");
    }
    times_.push_back(k.t_s);
    positions_.emplace_back(k.position[0], k.position[1], k.position[2]);
    glm::dquat q = attitude_from_hpr({k.heading_deg, k.pitch_deg, k.roll_deg});
    // q and -q are the same rotation; keep neighbours in the same hemisphere
    // so that slerp between them takes the short way round.
    if (!attitudes_.empty() && glm::dot(attitudes_.back(), q) < 0.0) q = -q;
    attitudes_.push_back(q);
  }

  // Tangents (dp/dt). Interior keys: the derivative at the middle key of the
  // parabola through three neighbours, i.e. the two adjacent secant slopes
  // weighted by the opposite gap, which is exact for quadratic motion at
  // uneven key spacing (Catmull-Rom generalised to non-uniform times). End
  // keys: the one-sided secant slope.
  tangents_.assign(n, glm::dvec3(0.0));
  if (n >= 2) {
    tangents_[0] = (positions_[1] - positions_[0]) / (times_[1] - times_[0]);
    tangents_[n - 1] = (positions_[n - 1] - positions_[n - 2]) / (times_[n - 1] - times_[n - 2]);
    for (std::size_t i = 1; i + 1 < n; ++i) {
      const double h0 = times_[i] - times_[i - 1];
      const double h1 = times_[i + 1] - times_[i];
      const glm::dvec3 d0 = (positions_[i] - positions_[i - 1]) / h0;
      const glm::dvec3 d1 = (positions_[i + 1] - positions_[i]) / h1;
      tangents_[i] = (d0 * h1 + d1 * h0) / (h0 + h1);
    }
  }
}

Pose PathInterpolator::sample(double t_s) const {
  const std::size_t n = times_.size();
  Pose pose;
  // NaN also lands here: !(NaN > x) is true.
  if (n == 1 || !(t_s > times_.front())) {
    pose.position = positions_.front();
    pose.attitude = attitudes_.front();
    return pose;
  }
  if (t_s >= times_.back()) {
    pose.position = positions_.back();
    pose.attitude = attitudes_.back();
    return pose;
  }
  // Segment [i, i+1] with times_[i] <= t < times_[i+1].
  const auto it = std::upper_bound(times_.begin(), times_.end(), t_s);
  const std::size_t i = static_cast<std::size_t>(it - times_.begin()) - 1;
  const double h = times_[i + 1] - times_[i];
  const double s = std::clamp((t_s - times_[i]) / h, 0.0, 1.0);

  const double s2 = s * s;
  const double s3 = s2 * s;
  const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
  const double h10 = s3 - 2.0 * s2 + s;
  const double h01 = -2.0 * s3 + 3.0 * s2;
  const double h11 = s3 - s2;
  pose.position = positions_[i] * h00 + tangents_[i] * (h10 * h) + positions_[i + 1] * h01 +
                  tangents_[i + 1] * (h11 * h);
  pose.attitude = slerp_short(attitudes_[i], attitudes_[i + 1], s);
  return pose;
}

}  // namespace ig::io
