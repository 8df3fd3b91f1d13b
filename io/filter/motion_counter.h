#pragma once
// A packet counter read from the motion of a stream that has none and no
// sender clock but carries velocities (FlightGear's FGNetFDM). The distance
// flown since the previous packet over the mean of the two speeds is the
// sender time between them, whenever they arrived; in periods of the sender
// clock's estimate it is the counter's step. So a loaded receiver that
// delays some packets and bunches others no longer makes the SenderClock
// guess the step from the arrival gap (a bunched pair counted as one period
// apart played out at up to twice the flown speed). Below kMinSpeedMps the
// motion says too little and the arrival gap decides, as without it.
// docs/pose-filter.md, "Sender clock".

#include <cstdint>
#include <optional>

#include <glm/vec3.hpp>

namespace ig::io {

class MotionCounter {
 public:
  static constexpr double kMinSpeedMps = 2.0;
  // The counter for a packet at `position` (metres) moving at `velocity`
  // (m/s) received at receive_s, the sender's period estimated as period_s.
  // Steps at least 1 forward; a packet that is not ahead of the newest
  // along the motion (a duplicate, a reordered one) gets a count at or
  // before the newest's. The first packet of a stream is 0.
  std::uint32_t next(const glm::dvec3& position, const glm::dvec3& velocity, double receive_s, double period_s);
  void reset() { started_ = false; }

 private:
  bool started_ = false;
  std::uint32_t count_ = 0;
  glm::dvec3 position_{0.0}, velocity_{0.0};
  double receive_s_ = 0.0;
};

}  // namespace ig::io
