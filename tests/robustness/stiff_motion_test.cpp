// Stiff motion through the pose filter (io/filter/pose_filter.h): the
// rendered pose stays inside the envelope of its input and its timeline never
// runs backwards (bounds: robustness/stiff_motion_support.h).
#include <gtest/gtest.h>

#include "robustness/stiff_motion_support.h"

namespace {

using namespace stiff_motion;

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

// No NaN, and every output inside its input's envelope (to rounding).
void expect_inside_envelope(const RunResult& r) {
  EXPECT_EQ(r.non_finite, 0);
  EXPECT_LT(r.env.worst_pos_excess, 1e-6);
  EXPECT_LT(r.env.worst_att_excess, 1e-7);
}

TEST(StiffMotionFilter, Roll720DegreesPerSecondNeverReverses) {
  const RunResult r = run_filter(roll_720(), {});
  print("720 deg/s roll", r);
  expect_inside_envelope(r);
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
  expect_inside_envelope(r);
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
  expect_inside_envelope(r);
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
  expect_inside_envelope(r);
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
  expect_inside_envelope(r);
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
  expect_inside_envelope(r);
  // Extrapolating 0.2 s through a 2 g turn: at most a t^2 / 2 = 0.39 m off, plus the turn's rotation.
  EXPECT_LT(r.worst_truth_pos, 0.5);
  int extrapolated = 0;
  for (const auto& o : r.out) extrapolated += o.mode != FilteredPose::Interpolating;
  EXPECT_GT(extrapolated, 3);
}

}  // namespace
