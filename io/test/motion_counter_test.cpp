// A packet counter from motion (io/filter/motion_counter.h), and the pose
// filter on a FlightGear-shaped stream (30 Hz, velocities, no counter, no
// sender time) received by a loaded machine: each packet delayed by up to
// DELAY, so some arrive late and others bunch behind them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "io/filter/motion_counter.h"
#include "io/filter/pose_filter.h"

namespace {

using ig::io::MotionCounter;

TEST(MotionCounter, CountsTheSenderPeriodsFlownNotTheArrivalGap) {
  MotionCounter m;
  const glm::dvec3 v(40.0, 0.0, 0.0);
  const double p = 1.0 / 60.0;  // the clock's estimate: a 30 Hz sender's packets are 2 periods apart
  EXPECT_EQ(m.next({0.0, 0.0, 0.0}, v, 0.000, p), 0u);
  EXPECT_EQ(m.next({40.0 / 30.0, 0.0, 0.0}, v, 0.040, p), 2u);        // arrived 7 ms late
  EXPECT_EQ(m.next({80.0 / 30.0, 0.0, 0.0}, v, 0.041, p), 4u);        // bunched 1 ms behind it
  EXPECT_EQ(m.next({200.0 / 30.0, 0.0, 0.0}, v, 0.170, p), 10u);      // a 100 ms stall of the sender
  EXPECT_EQ(m.next({200.0 / 30.0, 0.0, 0.0}, v, 0.171, p), 10u);      // a duplicate: not ahead
  EXPECT_EQ(m.next({160.0 / 30.0, 0.0, 0.0}, v, 0.172, p), 8u);       // a reordered one: behind
  EXPECT_EQ(m.next({240.0 / 30.0, 0.0, 0.0}, v, 0.200, p), 12u);      // the newest was kept
  // Parked: the motion says nothing, the arrival gap decides.
  MotionCounter slow;
  const glm::dvec3 still(0.5, 0.0, 0.0);
  EXPECT_EQ(slow.next({0.0, 0.0, 0.0}, still, 0.0, p), 0u);
  EXPECT_EQ(slow.next({0.0, 0.0, 0.0}, still, 0.050, p), 3u);
}

// Fastest apparent speed between 60 Hz frames over the flown speed, for a
// 30 Hz stream at 40 m/s delayed by up to `delay_s` (uniform), with or
// without its velocities.
double fastest_frame(double delay_s, bool velocities, std::uint32_t seed) {
  ig::io::PoseFilter filter;
  std::mt19937 rng(seed);
  const double speed = 40.0, period = 1.0 / 30.0;
  // Arrivals: each send delayed, in order (one socket), 0.5 ms apart at least.
  std::vector<double> arrival(200);
  for (std::size_t k = 0; k < arrival.size(); ++k) {
    const double delay = delay_s * double(rng() % 1000) / 1000.0;
    arrival[k] = std::max(double(k) * period + delay, k ? arrival[k - 1] + 0.0005 : 0.0);
  }
  double worst = 0.0;
  glm::dvec3 last_pos(0.0);
  bool have_last = false;
  std::size_t next = 0;
  for (int frame = 0; frame < 60 * 4; ++frame) {
    const double now = 0.1 + frame / 60.0;
    for (; next < arrival.size() && arrival[next] <= now; ++next) {
      ig::io::PoseSample s;
      s.receive_time_s = arrival[next];
      s.position = glm::dvec3(speed * double(next) * period, 0.0, 500.0);
      if (velocities) s.velocity_mps = glm::dvec3(speed, 0.0, 0.0);
      filter.push(s);
    }
    const auto out = filter.sample(now);
    if (!out) continue;
    if (have_last) worst = std::max(worst, glm::length(out->position - last_pos) * 60.0 / speed);
    last_pos = out->position;
    have_last = true;
  }
  return worst;
}

TEST(MotionCounter, ALoadedReceiverDoesNotSpeedTheStreamUp) {
  for (double delay_ms : {10.0, 15.0}) {
    double with = 0.0, without = 0.0;
    for (std::uint32_t seed = 1; seed <= 5; ++seed) {
      with = std::max(with, fastest_frame(delay_ms / 1000.0, true, seed));
      without = std::max(without, fastest_frame(delay_ms / 1000.0, false, seed));
    }
    std::printf("30 Hz, delays up to %.0f ms: fastest frame %.2fx the flown speed with velocities, %.2fx without\n",
                delay_ms, with, without);
    EXPECT_LE(with, 1.5) << delay_ms;
  }
}

}  // namespace
