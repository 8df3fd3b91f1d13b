// Stiff motion (issue 8, item 4): 720 deg/s rolls, 10 g pull-ups through the
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
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>

#include "io/filter/pose_filter.h"
#include "io/filter/quat_util.h"
#include "io/path_interpolator.h"
#include "io/pose.h"
#include "robustness_support.h"

namespace {

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

glm::dquat about_x(double rad) { return ig::io::quat::exp_rotvec({rad, 0.0, 0.0}); }

Motion roll_720() {  // 720 deg/s roll, straight and level at 120 m/s
  return [](double t) {
    return State{{60.0 * t, 104.0 * t, 1500.0}, ig::io::attitude_from_hpr({30.0, 0.0, 720.0 * t})};
  };
}
Motion pull_up_10g() {  // 10 g at 200 m/s: 28 deg/s, through the vertical and over the top
  return [](double t) {
    const double v = 200.0, w = 10.0 * kG / v, r = v / w, a = w * t;
    return State{{0.0, r * std::sin(a), 2000.0 + r * (1.0 - std::cos(a))}, about_x(a)};
  };
}
Motion heading_through_north() {  // heading 0 -> 60 -> 0 -> 300 -> 0 ..., 94 deg/s peak
  return [](double t) {
    return State{{0.0, 100.0 * t, 800.0}, ig::io::attitude_from_hpr({60.0 * std::sin(2 * kPi * t / 4.0), 5.0, 10.0})};
  };
}
Motion turn_2g() {  // 2 g level turn
  return [](double t) {
    const double v = 150.0, r = v * v / (2 * kG), w = v / r;
    return State{{r * (1 - std::cos(w * t)), r * std::sin(w * t), 1000.0},
                 ig::io::attitude_from_hpr({w * t * 180 / kPi, 0, 60})};
  };
}

glm::dvec3 velocity(const Motion& m, double t) { return (m(t + 1e-4).pos - m(t - 1e-4).pos) / 2e-4; }
// Body rates (p, q, r) deg/s, the PoseSample convention.
glm::dvec3 rates(const Motion& m, double t) {
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
void check_envelope(const FilteredPose& out, const std::vector<Input>& in, double max_extrap, Envelope& env) {
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

// ------------------------------------------------------------- filter run --

struct RunSpec {
  double duration_s = 6.0;
  double dropout_at_s = -1.0, dropout_len_s = 0.0;
  std::vector<std::pair<double, double>> sender_steps;  // (true t, sender clock offset from then on)
  std::vector<std::pair<double, double>> ig_steps;      // (true t, IG clock offset from then on)
};

struct RunResult {
  std::vector<FilteredPose> out;
  std::vector<double> now_true;  // true time of each output
  Envelope env;
  double worst_truth_pos = 0.0, worst_truth_att_deg = 0.0;  // vs the motion at the output's instant
  int non_finite = 0;
};

double step_at(const std::vector<std::pair<double, double>>& steps, double t) {
  double off = 0.0;
  for (auto [at, o] : steps)
    if (t >= at) off = o;
  return off;
}

RunResult run_filter(const Motion& m, const RunSpec& spec) {
  PoseFilter filter;
  RunResult r;
  std::vector<Input> received;  // this stream segment (since the last sender clock step)
  double segment_offset = 0.0;
  const int packets = int(spec.duration_s * kRate);
  int next = 0;
  for (int frame = 0;; ++frame) {
    const double now = 0.0037 + frame / kRate;  // true time
    if (now > spec.duration_s) break;
    while (next < packets && next / kRate + kLatency <= now) {
      const double t = next / kRate;
      ++next;
      if (spec.dropout_at_s >= 0 && t >= spec.dropout_at_s && t < spec.dropout_at_s + spec.dropout_len_s) continue;
      const double sender_off = step_at(spec.sender_steps, t);
      PoseSample s;
      s.receive_time_s = t + kLatency + step_at(spec.ig_steps, t + kLatency);
      s.sender_time_s = t + sender_off;
      s.sequence = std::uint32_t(next);
      const State st = m(t);
      s.position = st.pos;
      s.attitude = st.att;
      s.velocity_mps = velocity(m, t);
      s.body_rates_dps = rates(m, t);
      const auto jumps = filter.counters().time_jumps;
      if (filter.push(s)) {
        // A reset starts a new stream: the envelope is this packet's onwards.
        if (filter.counters().time_jumps != jumps) {
          received.clear();
          segment_offset = sender_off;
        }
        received.push_back(
            {*s.sender_time_s, st.pos, *s.velocity_mps, st.att, glm::length(*s.body_rates_dps) * kPi / 180});
      }
    }
    const auto out = filter.sample(now + step_at(spec.ig_steps, now));
    if (!out) continue;
    if (!(ig::io::quat::finite(out->position) && ig::io::quat::finite(out->attitude))) {
      ++r.non_finite;
      continue;
    }
    check_envelope(*out, received, filter.options().max_extrapolation_s, r.env);
    // Against the motion itself, after start-up (the first sample is held one playout delay).
    if (now > 0.5 && out->sample_time_s > received.front().t) {
      const State truth = m(out->sample_time_s - segment_offset);
      r.worst_truth_pos = std::max(r.worst_truth_pos, glm::length(out->position - truth.pos));
      r.worst_truth_att_deg = std::max(r.worst_truth_att_deg, angle_between(out->attitude, truth.att) * 180 / kPi);
    }
    r.out.push_back(*out);
    r.now_true.push_back(now);
  }
  return r;
}

void print(const char* name, const RunResult& r) {
  std::printf(
      "[stiff] filter %-34s outputs %zu, envelope excess pos %.2e m att %.2e deg, vs truth pos %.4f m att "
      "%.4f deg\n",
      name, r.out.size(), r.env.worst_pos_excess, r.env.worst_att_excess * 180 / kPi, r.worst_truth_pos,
      r.worst_truth_att_deg);
}

// Roll angle about body y relative to a level attitude at heading 30 (continuous, unwrapped by the caller).
// Frame to frame: the most the sample time ran back (s) and the largest position step (m).
struct FrameSteps {
  double back = 0.0, worst = 0.0;
};
FrameSteps frame_steps(const RunResult& r) {
  FrameSteps f;
  for (size_t k = 1; k < r.out.size(); ++k) {
    f.back = std::max(f.back, r.out[k - 1].sample_time_s - r.out[k].sample_time_s);
    f.worst = std::max(f.worst, glm::length(r.out[k].position - r.out[k - 1].position));
  }
  return f;
}

double roll_of(const glm::dquat& q) { return ig::io::hpr_from_attitude(q).roll_deg; }
double unwrap_step(double from, double to) { return std::remainder(to - from, 360.0); }

TEST(StiffMotionFilter, Roll720DegreesPerSecondNeverReverses) {
  const RunResult r = run_filter(roll_720(), {});
  print("720 deg/s roll", r);
  EXPECT_EQ(r.non_finite, 0);
  EXPECT_LT(r.env.worst_pos_excess, 1e-6);
  EXPECT_LT(r.env.worst_att_excess, 1e-7);
  EXPECT_LT(r.worst_truth_att_deg, 1e-3);
  double worst_step = 0.0;
  for (size_t k = 1; k < r.out.size(); ++k) {
    const double step = unwrap_step(roll_of(r.out[k - 1].attitude), roll_of(r.out[k].attitude));
    const double dt = r.out[k].sample_time_s - r.out[k - 1].sample_time_s;
    EXPECT_GE(step, -1e-6) << "roll reversed at output " << k;
    worst_step = std::max(worst_step, step / std::max(dt, 1e-9));
  }
  std::printf("[stiff] roll rate seen between frames at most %.1f deg/s (input 720)\n", worst_step);
  EXPECT_LT(worst_step, 720.0 * 1.01);
}

TEST(StiffMotionFilter, TenGPullUpThroughTheVertical) {
  const RunResult r = run_filter(pull_up_10g(), {});
  print("10 g pull-up", r);
  EXPECT_EQ(r.non_finite, 0);
  EXPECT_LT(r.env.worst_pos_excess, 1e-6);
  EXPECT_LT(r.env.worst_att_excess, 1e-7);
  EXPECT_LT(r.worst_truth_pos, 0.01);
  // The pitch angle (rotation about body x) only grows, through 90 degrees.
  double prev = -1.0, last = 0.0;
  for (const auto& o : r.out) {
    const glm::dvec3 v = ig::io::quat::log_rotvec(o.attitude);
    double a = v.x;
    while (a < prev - kPi) a += 2 * kPi;
    EXPECT_GE(a, prev - 1e-9);
    prev = last = a;
  }
  EXPECT_GT(last * 180 / kPi, 120.0) << "the run should pass the vertical";
}

TEST(StiffMotionFilter, HeadingSweepsThroughNorthBothWays) {
  const Motion m = heading_through_north();
  const RunResult r = run_filter(m, {});
  print("heading through north", r);
  EXPECT_LT(r.env.worst_pos_excess, 1e-6);
  EXPECT_LT(r.env.worst_att_excess, 1e-7);
  int crossings_up = 0, crossings_down = 0;
  for (size_t k = 1; k < r.out.size(); ++k) {
    const double h0 = ig::io::hpr_from_attitude(r.out[k - 1].attitude).heading_deg;
    const double h1 = ig::io::hpr_from_attitude(r.out[k].attitude).heading_deg;
    const double step = unwrap_step(h0, h1);
    const double dt = r.out[k].sample_time_s - r.out[k - 1].sample_time_s;
    EXPECT_LE(std::abs(step), 94.3 * dt * 1.05 + 1e-6) << "heading went the long way round at output " << k;
    const bool wrapped = std::abs(h1 - h0) > 180.0;
    if (wrapped && step > 0) ++crossings_up;
    if (wrapped && step < 0) ++crossings_down;
    EXPECT_TRUE(h1 <= 60.01 || h1 >= 299.99) << h1;
  }
  EXPECT_GE(crossings_up, 1);
  EXPECT_GE(crossings_down, 1);
}

TEST(StiffMotionFilter, HostClockJumpsBackAndForth) {
  // The host's clock (sender time) steps back 0.5 s, forward 0.5 s, back 5 s
  // and forward 3 s: small steps are inside time_jump_s, big ones reset.
  RunSpec spec;
  spec.duration_s = 8.0;
  spec.sender_steps = {{1.5, -0.5}, {3.0, 0.0}, {4.5, -5.0}, {6.0, -2.0}};
  const Motion m = turn_2g();
  const RunResult r = run_filter(m, spec);
  print("host clock -0.5/+0.5/-5/+3 s", r);
  EXPECT_EQ(r.non_finite, 0);
  EXPECT_LT(r.env.worst_pos_excess, 1e-6);
  EXPECT_LT(r.env.worst_att_excess, 1e-7);
  // Frame to frame the pose moves at most as the aircraft does over a frame
  // plus the playout delay it may skip or repeat at a reset (150 m/s).
  const double worst = frame_steps(r).worst;
  std::printf("[stiff] host clock jumps: largest frame-to-frame step %.2f m (2.5 m per frame at 150 m/s)\n", worst);
  EXPECT_LT(worst, 150.0 * (1.0 / kRate + 0.1));
}

// The IG's own clock (receive stamps and sample()) is a steady clock in the
// product, so it cannot step; a caller that breaks sample()'s precondition
// (non-decreasing clock) still gets a bounded pose.
TEST(StiffMotionFilter, IgClockStepsBack) {
  RunSpec spec;
  spec.ig_steps = {{2.0, -0.5}, {4.0, -1.0}};
  const RunResult r = run_filter(turn_2g(), spec);
  print("IG clock -0.5 s twice", r);
  EXPECT_EQ(r.non_finite, 0);
  EXPECT_LT(r.env.worst_pos_excess, 1e-6);
  EXPECT_LT(r.env.worst_att_excess, 1e-7);
  const auto [back, worst] = frame_steps(r);
  std::printf("[stiff] IG clock steps back: timeline ran back by %.4f s, largest frame step %.2f m\n", back, worst);
  EXPECT_LE(back, 0.0) << "the past was replayed";
  EXPECT_LT(worst, 150.0 * (1.0 / kRate + 0.1));
}

TEST(StiffMotionFilter, IgClockStepsForward) {
  // Looks like the newest data aging at once: extrapolation (at most 0.2 s),
  // then, after clock_step_s, a reset back onto the stream's own timeline.
  RunSpec spec;
  spec.ig_steps = {{2.0, 0.5}, {4.0, 1.0}};
  const RunResult r = run_filter(turn_2g(), spec);
  print("IG clock +0.5 s twice", r);
  EXPECT_EQ(r.non_finite, 0);
  EXPECT_LT(r.env.worst_pos_excess, 1e-6);
  EXPECT_LT(r.env.worst_att_excess, 1e-7);
  const auto [back, worst] = frame_steps(r);
  // The playout instant ran ahead by the step, but the pose only by the
  // 0.2 s extrapolation limit: stepping back onto the timeline moves it back
  // by at most that plus one playout delay of motion.
  std::printf("[stiff] IG clock steps forward: playout instant ran back by %.4f s, largest frame step %.2f m\n", back,
              worst);
  EXPECT_LT(worst, 150.0 * (1.0 / kRate + 0.2 + 0.1));
}

TEST(StiffMotionFilter, TwoHundredMillisecondDropouts) {
  RunSpec spec;
  spec.dropout_at_s = 2.0;
  spec.dropout_len_s = 0.2;
  const Motion m = turn_2g();
  const RunResult r = run_filter(m, spec);
  print("200 ms dropout, 2 g turn", r);
  EXPECT_EQ(r.non_finite, 0);
  EXPECT_LT(r.env.worst_pos_excess, 1e-6);
  EXPECT_LT(r.env.worst_att_excess, 1e-7);
  // Extrapolating 0.2 s through a 2 g turn: at most a t^2 / 2 = 0.39 m off, plus the turn's rotation.
  EXPECT_LT(r.worst_truth_pos, 0.5);
  int extrapolated = 0;
  for (const auto& o : r.out) extrapolated += o.mode != FilteredPose::Interpolating;
  EXPECT_GT(extrapolated, 3);
}

// --------------------------------------------------------- scripted path --

// Keys of a motion every dt seconds; the path sampled at 240 Hz must stay in the envelope.
struct PathRun {
  std::vector<ig::io::Pose> poses;
  Envelope env;
  double worst_truth_pos = 0.0;
};

PathRun run_path(const Motion& m, double key_dt, double duration, double max_bulge_m) {
  ig::io::PathSpec spec;
  std::vector<Input> keys;
  for (double t = 0; t <= duration + 1e-9; t += key_dt) {
    const State s = m(t);
    ig::io::PathKey k;
    k.t_s = t;
    k.position = {s.pos.x, s.pos.y, s.pos.z};
    const auto hpr = ig::io::hpr_from_attitude(s.att);
    k.heading_deg = hpr.heading_deg;
    k.pitch_deg = hpr.pitch_deg;
    k.roll_deg = hpr.roll_deg;
    spec.keys.push_back(k);
    keys.push_back({t, s.pos, glm::dvec3(0.0), ig::io::attitude_from_hpr(hpr), 0.0});
  }
  const ig::io::PathInterpolator path(spec);
  PathRun r;
  for (double t = 0; t <= duration; t += 1.0 / 240) {
    const ig::io::Pose p = path.sample(t);
    r.poses.push_back(p);
    FilteredPose as_out;
    as_out.position = p.position;
    as_out.attitude = p.attitude;
    as_out.sample_time_s = t;
    // Catmull-Rom tangents are not the keys' velocities: check against the box grown by the stated bound.
    Envelope e;
    check_envelope(as_out, keys, 0.0, e);
    r.env.worst_pos_excess = std::max(r.env.worst_pos_excess, e.worst_pos_excess - max_bulge_m);
    r.env.worst_att_excess = std::max(r.env.worst_att_excess, e.worst_att_excess);
    r.worst_truth_pos = std::max(r.worst_truth_pos, glm::length(p.position - m(t).pos));
  }
  return r;
}

TEST(StiffMotionPath, Roll720KeysEvery30thOfASecond) {
  const PathRun r = run_path(roll_720(), 1.0 / 30, 2.0, 0.0);
  std::printf("[stiff] path 720 deg/s roll, keys 24 deg apart: envelope excess pos %.2e m att %.2e deg\n",
              r.env.worst_pos_excess, r.env.worst_att_excess * 180 / kPi);
  EXPECT_LT(r.env.worst_pos_excess, 1e-6);
  EXPECT_LT(r.env.worst_att_excess, 1e-7);
  for (size_t k = 1; k < r.poses.size(); ++k)
    EXPECT_GE(unwrap_step(roll_of(r.poses[k - 1].attitude), roll_of(r.poses[k].attitude)), -1e-6) << k;
}

TEST(StiffMotionPath, TenGPullUpKeysEveryTwentiethOfASecond) {
  // Catmull-Rom through keys 0.05 s apart on a 408 m circle: stated bound 5 cm outside the keys' box.
  const PathRun r = run_path(pull_up_10g(), 0.05, 8.0, 0.05);
  std::printf(
      "[stiff] path 10 g pull-up: envelope excess pos %.2e m (beyond 5 cm) att %.2e deg, off the circle %.4f m\n",
      r.env.worst_pos_excess, r.env.worst_att_excess * 180 / kPi, r.worst_truth_pos);
  EXPECT_LE(r.env.worst_pos_excess, 0.0);
  EXPECT_LT(r.env.worst_att_excess, 1e-7);
  EXPECT_LT(r.worst_truth_pos, 0.05);
}

TEST(StiffMotionPath, HeadingThroughNorthBothWays) {
  const PathRun r = run_path(heading_through_north(), 0.1, 8.0, 0.0);
  EXPECT_LT(r.env.worst_att_excess, 1e-7);
  for (size_t k = 1; k < r.poses.size(); ++k) {
    const double h0 = ig::io::hpr_from_attitude(r.poses[k - 1].attitude).heading_deg;
    const double h1 = ig::io::hpr_from_attitude(r.poses[k].attitude).heading_deg;
    EXPECT_LT(std::abs(unwrap_step(h0, h1)), 1.0) << "long way round at sample " << k;
    EXPECT_TRUE(h1 <= 60.01 || h1 >= 299.99) << h1;
  }
}

// ----------------------------------------------------- E over stiff motion --

// Renders the two-level method over poses; returns E's largest step within a
// mode (hit->hit or miss->miss) and at a switch, in metres.
struct ETrack {
  double within = 0.0, at_switch = 0.0;
  int switches = 0;
};

ETrack track_e(const std::vector<ig::render::Camera>& cams, const ig::terrain::Heightfield& hf) {
  robustness::Rig rig(hf, "twolevel", 80, 60);
  auto* tl = robustness::as_twolevel(rig.method());
  ETrack t;
  glm::dvec3 prev{0.0};
  bool prev_hit = false;
  for (size_t k = 0; k < cams.size(); ++k) {
    const auto f = rig.render(cams[k]);
    EXPECT_EQ(robustness::finite_problems(f), "") << "frame " << k;
    const auto& e = tl->look_at();
    if (k > 0) {
      const double step = glm::length(glm::dvec2(e.point - prev));
      if (e.hit == prev_hit) {
        t.within = std::max(t.within, step);
      } else {
        t.at_switch = std::max(t.at_switch, step);
        ++t.switches;
      }
    }
    prev = e.point;
    prev_hit = e.hit;
  }
  return t;
}

TEST(StiffMotionLevel1Centre, RollAboutTheViewAxisLeavesEPut) {
  const auto hf = robustness::hills();
  std::vector<ig::render::Camera> cams;
  for (int k = 0; k < 30; ++k)
    cams.push_back(robustness::camera_at({2000, 2500, hf.max_m + 100}, 40, -20, 720.0 * k / kRate, 60, 80, 60));
  const ETrack t = track_e(cams, hf);
  std::printf("[stiff] E under a 720 deg/s roll: largest step %.3f m\n", t.within);
  EXPECT_EQ(t.switches, 0);
  EXPECT_LT(t.within, 1e-6);
}

TEST(StiffMotionLevel1Centre, PullUpThroughTheHorizonHasNoExtraJump) {
  // 10 g pull-up from 5 degrees nose down, 60 Hz: the centre ray leaves the
  // terrain; E's step at that switch is no larger than its steps while hitting.
  const auto hf = robustness::hills();
  std::vector<ig::render::Camera> cams;
  const double w = 10.0 * kG / 200.0 * 180.0 / kPi;  // deg/s
  const glm::dvec3 eye(1500, 1500, hf.sample_surface(1500, 1500) + 80);
  for (int k = 0; k < 60; ++k) cams.push_back(robustness::camera_at(eye, 45, -5.0 + w * k / kRate, 0, 60, 80, 60));
  const ETrack up = track_e(cams, hf);
  std::reverse(cams.begin(), cams.end());
  const ETrack down = track_e(cams, hf);
  std::printf(
      "[stiff] E over a 10 g pull-up (%.1f deg/frame): largest step while hitting %.0f m, at the switch %.0f m "
      "(%d switches); pushing over: %.0f m, at the switch %.0f m (%d)\n",
      w / kRate, up.within, up.at_switch, up.switches, down.within, down.at_switch, down.switches);
  EXPECT_GE(up.switches, 1);
  EXPECT_GE(down.switches, 1);
  EXPECT_LE(up.at_switch, up.within + hf.spacing_x_m);
  EXPECT_LE(down.at_switch, down.within + hf.spacing_x_m);
}

}  // namespace
