#pragma once
// Stiff motion: 720 deg/s rolls, 10 g pull-ups through the
// vertical, heading sweeps through north both ways, host (sender) and IG
// clock jumps back and forth, 200 ms dropouts. For the scripted path
// (io/path_interpolator.h) and the pose filter (io/filter/pose_filter.h) the
// rendered pose must stay inside the envelope of its input, with stated
// bounds:
//  * interpolated position: inside the box of the two bracketing inputs,
//    grown by the cubic's bulge (4/27) h (|v_a - c| + |v_b - c|), c = chord
//    velocity (zero for linear interpolation; Catmull-Rom keys: 5 cm);
//  * interpolated attitude: on the rotation arc between the two inputs;
//  * extrapolated / held: within max_extrapolation_s * |v| (and * |omega|)
//    of the newest input;
//  * the timeline never runs backwards (rolls never reverse, headings never
//    go the long way round).
// Then the two-level method's Level1 centre E over the same motions.
// The filter cases are stiff_motion_test.cpp, the scripted path and E
// stiff_motion_path_test.cpp; this header holds the motions and the envelope
// check they share.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>

#include "io/filter/pose_filter.h"
#include "io/filter/quat_util.h"
#include "io/path_interpolator.h"
#include "io/pose.h"
#include "robustness/robustness_support.h"

namespace stiff_motion {

using ig::io::FilteredPose;
using ig::io::PoseFilter;
using ig::io::PoseSample;
using ig::io::quat::angle_between;

constexpr double kPi = 3.14159265358979323846;
constexpr double kG = 9.80665;
constexpr double kRate = 60.0;
constexpr double kLatency = 0.020;

struct State {
  glm::dvec3 pos;
  glm::dquat att;
};
using Motion = std::function<State(double)>;

inline glm::dquat about_x(double rad) { return ig::io::quat::exp_rotvec({rad, 0.0, 0.0}); }

inline Motion roll_720() {  // 720 deg/s roll, straight and level at 120 m/s
  return [](double t) {
    return State{{60.0 * t, 104.0 * t, 1500.0}, ig::io::attitude_from_hpr({30.0, 0.0, 720.0 * t})};
  };
}
inline Motion pull_up_10g() {  // 10 g at 200 m/s: 28 deg/s, through the vertical and over the top
  return [](double t) {
    const double v = 200.0, w = 10.0 * kG / v, r = v / w, a = w * t;
    return State{{0.0, r * std::sin(a), 2000.0 + r * (1.0 - std::cos(a))}, about_x(a)};
  };
}
inline Motion heading_through_north() {  // heading 0 -> 60 -> 0 -> 300 -> 0 ..., 94 deg/s peak
  return [](double t) {
    return State{{0.0, 100.0 * t, 800.0}, ig::io::attitude_from_hpr({60.0 * std::sin(2 * kPi * t / 4.0), 5.0, 10.0})};
  };
}
inline Motion turn_2g() {  // 2 g level turn
  return [](double t) {
    const double v = 150.0, r = v * v / (2 * kG), w = v / r;
    return State{{r * (1 - std::cos(w * t)), r * std::sin(w * t), 1000.0},
                 ig::io::attitude_from_hpr({w * t * 180 / kPi, 0, 60})};
  };
}

inline glm::dvec3 velocity(const Motion& m, double t) { return (m(t + 1e-4).pos - m(t - 1e-4).pos) / 2e-4; }
// Body rates (p, q, r) deg/s, the PoseSample convention.
inline glm::dvec3 rates(const Motion& m, double t) {
  const glm::dvec3 w = ig::io::quat::log_rotvec(glm::conjugate(m(t - 1e-4).att) * m(t + 1e-4).att) / 2e-4;
  return glm::dvec3(w.y, w.x, -w.z) * (180.0 / kPi);
}

// ------------------------------------------------------------ envelope --

struct Input {
  double t;  // stream time (sender clock)
  glm::dvec3 pos, vel;
  glm::dquat att;
  double omega;  // |angular rate|, rad/s
};

struct Envelope {
  double worst_pos_excess = 0.0;  // metres outside the stated position envelope
  double worst_att_excess = 0.0;  // radians off the arc / beyond the extrapolation bound
};

// Checks one output against the inputs the filter has received (sorted by t).
inline void check_envelope(const FilteredPose& out, const std::vector<Input>& in, double max_extrap, Envelope& env) {
  const double tau = out.sample_time_s;
  if (in.empty()) return;
  auto excess_box = [&](const glm::dvec3& p, const Input& a, const Input& b, double margin) {
    double e = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double lo = std::min(a.pos[k], b.pos[k]) - margin, hi = std::max(a.pos[k], b.pos[k]) + margin;
      e = std::max({e, lo - p[k], p[k] - hi});
    }
    return e;
  };
  if (tau <= in.front().t) {  // held at the oldest
    env.worst_pos_excess = std::max(env.worst_pos_excess, glm::length(out.position - in.front().pos));
    return;
  }
  if (tau > in.back().t) {  // extrapolated / held past the newest
    const Input& n = in.back();
    const double dt = std::min(tau - n.t, max_extrap);
    env.worst_pos_excess =
        std::max(env.worst_pos_excess, glm::length(out.position - n.pos) - glm::length(n.vel) * dt - 1e-6);
    env.worst_att_excess = std::max(env.worst_att_excess, angle_between(out.attitude, n.att) - n.omega * dt - 1e-9);
    return;
  }
  size_t k = 1;
  while (in[k].t < tau) ++k;
  const Input &a = in[k - 1], &b = in[k];
  const double h = b.t - a.t;
  const glm::dvec3 c = (b.pos - a.pos) / h;
  const double bulge = 4.0 / 27.0 * h * (glm::length(a.vel - c) + glm::length(b.vel - c));
  env.worst_pos_excess = std::max(env.worst_pos_excess, excess_box(out.position, a, b, bulge + 1e-6));
  const double arc =
      angle_between(a.att, out.attitude) + angle_between(out.attitude, b.att) - angle_between(a.att, b.att);
  env.worst_att_excess = std::max(env.worst_att_excess, arc - 1e-9);
}

inline double roll_of(const glm::dquat& q) { return ig::io::hpr_from_attitude(q).roll_deg; }
inline double unwrap_step(double from, double to) { return std::remainder(to - from, 360.0); }

}  // namespace stiff_motion
