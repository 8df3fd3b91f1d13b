#include "environment/sun_tracker.h"

#include <cmath>

namespace ig::environment {
namespace {
constexpr double kMetresPerDegree = 111195.0;  // of latitude, on a sphere of the Earth's mean radius
constexpr double kDegToRad = 0.017453292519943295;
}  // namespace

bool SunTracker::reusable(double seconds_after, const Observer& o) const {
  if (!last_ || !(std::fabs(seconds_after - last_seconds_) < kReuseSeconds)) return false;
  const double north_m = (o.latitude_deg - last_observer_.latitude_deg) * kMetresPerDegree;
  const double east_m = std::remainder(o.longitude_deg - last_observer_.longitude_deg, 360.0) * kMetresPerDegree *
                        std::cos(o.latitude_deg * kDegToRad);
  return std::hypot(north_m, east_m) < kReuseDistanceM &&
         std::fabs(o.height_m - last_observer_.height_m) < kReuseDistanceM;
}

const SunPosition& SunTracker::at(double seconds_after, const Observer& o) {
  if (!reusable(seconds_after, o)) {
    last_ = sun_position(start_, seconds_after, o);
    last_seconds_ = seconds_after;
    last_observer_ = o;
    ++computations_;
  }
  return *last_;
}

}  // namespace ig::environment
