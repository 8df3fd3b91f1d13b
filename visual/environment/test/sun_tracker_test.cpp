// The per-frame sun reuses its last result only while that stays within a
// hundredth of a degree of the exact one (environment/sun_tracker.h).
#include "environment/sun_tracker.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

namespace {

using ig::environment::Observer;
using ig::environment::SunTracker;

double angle_deg(const ig::environment::SunPosition& a, const ig::environment::SunPosition& b) {
  const glm::dvec3 u = a.enu(), v = b.enu();
  return std::acos(std::clamp(u.x * v.x + u.y * v.y + u.z * v.z, -1.0, 1.0)) * 180.0 / M_PI;
}

TEST(SunTracker, ReusesWithinASecondAndHalfAKilometre) {
  const ig::options::UtcDateTime start{2026, 6, 21, 19, 40, 0.0};
  SunTracker tracker(start);
  // A 60 Hz flight at 250 m/s: each frame moves the eye 4 m north.
  double worst = 0.0;
  const int frames = 600;
  for (int k = 0; k < frames; ++k) {
    const double t = k / 60.0;
    const Observer eye{46.5 + (4.0 * k) / 111195.0, 7.9, 1500.0};
    const auto& tracked = tracker.at(t, eye);
    worst = std::max(worst, angle_deg(tracked, ig::environment::sun_position(start, t, eye)));
  }
  EXPECT_LT(worst, 0.01);
  // 10 s of clock: at most one computation a second (and one per 500 m: 2.4 km flown).
  EXPECT_LE(tracker.computations(), 11);
  EXPECT_GE(tracker.computations(), 10);
}

TEST(SunTracker, AJumpRecomputes) {
  const ig::options::UtcDateTime start{2026, 6, 21, 12, 0, 0.0};
  SunTracker tracker(start);
  tracker.at(0.0, Observer{46.5, 7.9, 0.0});
  tracker.at(0.5, Observer{46.5, 7.9, 0.0});
  EXPECT_EQ(tracker.computations(), 1);
  tracker.at(0.5, Observer{46.5, 8.0, 0.0});  // 7.7 km east
  EXPECT_EQ(tracker.computations(), 2);
  tracker.at(0.5, Observer{46.5, 8.0, 900.0});  // 900 m up
  EXPECT_EQ(tracker.computations(), 3);
  tracker.at(-3600.0, Observer{46.5, 8.0, 900.0});  // an hour back (a replay rewound)
  EXPECT_EQ(tracker.computations(), 4);
}

}  // namespace
