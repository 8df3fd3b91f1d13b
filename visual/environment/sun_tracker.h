#pragma once
// The sun each frame for a moving eye, without paying for the ephemeris
// every frame: sun_position costs about 0.15 ms (the Earth's ephemeris and
// the precession-nutation series), while the sun moves at most 0.0042 deg
// a second and 0.01 deg for a kilometre of travel. So a result is reused
// while the clock stays within kReuseSeconds and the eye within
// kReuseDistanceM (horizontally and vertically) of where it was computed:
// the direction is then at most about 0.01 deg off, a quarter of a pixel at
// 45 deg over 1080 rows. No GL.

#include <optional>

#include "environment/sun_position.h"
#include "options/shading_options.h"

namespace ig::environment {

class SunTracker {
 public:
  static constexpr double kReuseSeconds = 1.0;
  static constexpr double kReuseDistanceM = 500.0;

  // The clock's UTC time at seconds_after = 0.
  explicit SunTracker(const options::UtcDateTime& start) : start_(start) {}

  // The sun at start + seconds_after seen from `observer` (standard atmosphere
  // at its height). Throws as sun_position does.
  const SunPosition& at(double seconds_after, const Observer& observer);
  // How many times the ephemeris was computed (tests).
  int computations() const { return computations_; }

 private:
  bool reusable(double seconds_after, const Observer& observer) const;

  options::UtcDateTime start_;
  std::optional<SunPosition> last_;
  double last_seconds_ = 0.0;
  Observer last_observer_;
  int computations_ = 0;
};

}  // namespace ig::environment
