#include "io/filter/motion_counter.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace ig::io {

std::uint32_t MotionCounter::next(const glm::dvec3& position, const glm::dvec3& velocity, double receive_s,
                                  double period_s) {
  if (started_ && period_s > 0.0) {
    const double speed = 0.5 * (glm::length(velocity) + glm::length(velocity_));
    if (speed >= kMinSpeedMps) {
      // Signed along the mean velocity: a packet from behind the newest
      // (duplicated or reordered) gets a count at or before it, which the
      // SenderClock treats as stale, and the newest stays the reference.
      const glm::dvec3 heading = (velocity + velocity_) / std::max(glm::length(velocity + velocity_), 1e-9);
      const double periods = glm::dot(position - position_, heading) / speed / period_s;
      if (periods < 0.25) return count_ - std::uint32_t(std::clamp<double>(std::round(-periods), 0.0, 100000.0));
      count_ += std::uint32_t(std::clamp<double>(std::round(periods), 1.0, 100000.0));
    } else {
      // Too slow to time by motion: the arrival gap, as the SenderClock would.
      count_ += std::uint32_t(std::clamp<double>(std::round((receive_s - receive_s_) / period_s), 1.0, 100000.0));
    }
  } else {
    count_ = 0;
  }
  started_ = true;
  position_ = position;
  velocity_ = velocity;
  receive_s_ = receive_s;
  return count_;
}

}  // namespace ig::io
