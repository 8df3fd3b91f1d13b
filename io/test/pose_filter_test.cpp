// PoseFilter (io/filter/pose_filter.h) against analytic truth trajectories
// sent as a 60 Hz packet stream, sampled by a 60 Hz render clock: stiff
// motion, heading wrap, receive-time-only streams and sequence wraps. The
// printed "[filter]" lines are the measured error table of
// docs/pose-filter.md; the impairments are pose_filter_impairments_test.cpp.
#include "io/filter/pose_filter.h"

#include <gtest/gtest.h>

#include "io/test/pose_filter_test_support.h"

namespace {

using namespace pose_filter_test;

TEST(PoseFilter, NothingBeforeFirstValidSample) {
  PoseFilter f;
  EXPECT_FALSE(f.sample(0.0).has_value());
  PoseSample bad;
  bad.receive_time_s = 0.0;
  bad.position = {std::nan(""), 0, 0};
  EXPECT_FALSE(f.push(bad));
  bad.position = {0, 0, 0};
  bad.attitude = glm::dquat(0, 0, 0, 0);
  EXPECT_FALSE(f.push(bad));
  bad.attitude = glm::dquat(1, 0, 0, 0);
  bad.velocity_mps = glm::dvec3(0, INFINITY, 0);
  EXPECT_FALSE(f.push(bad));
  bad.velocity_mps.reset();
  bad.sender_time_s = NAN;
  EXPECT_FALSE(f.push(bad));
  EXPECT_EQ(f.counters().non_finite, 4u);
  EXPECT_FALSE(f.sample(0.1).has_value());
  bad.sender_time_s = 0.0;
  EXPECT_TRUE(f.push(bad));
  const auto out = f.sample(NAN);  // non-finite clock: still a finite pose
  ASSERT_TRUE(out.has_value());
  EXPECT_TRUE(finite_pose(*out));
}

TEST(PoseFilter, Roll720DegPerSecond) {
  const Truth tr = roll_720();
  StreamSpec sp;
  PoseFilter f;
  const auto st = run(f, tr, make_stream(tr, sp, 1), sp.duration_s);
  report("(a) roll 720 deg/s", st, f);
  EXPECT_EQ(st.nan, 0);
  EXPECT_LT(st.max_pos, 1e-6);
  EXPECT_LT(st.max_ang, 1e-6);  // constant-axis rate: slerp is exact
  EXPECT_LT(st.max_ang_nominal, 1.0);
  EXPECT_EQ(st.modes[1] + st.modes[2], 0);

  // Same roll with 50 % loss bursts and no rates: short-arc slerp still fine
  // up to 180 deg per gap; with rates the long arc is chosen correctly.
  sp.loss_burst_prob = 1.0;
  sp.burst_period_s = 1.0;
  sp.burst_len_s = 1.0;
  PoseFilter f2;
  const auto st2 = run(f2, tr, make_stream(tr, sp, 2), sp.duration_s);
  report("(a) roll 720 + 50% loss", st2, f2);
  EXPECT_EQ(st2.nan, 0);
  EXPECT_LT(st2.max_ang, 1e-6);
}

TEST(PoseFilter, Roll720LongGapFollowsRates) {
  // 0.3 s gap at 720 deg/s = 216 deg: the short arc goes the wrong way; the
  // body rates pick the right branch. Fixed 0.3 s delay so it interpolates.
  const Truth tr = roll_720();
  StreamSpec sp;
  sp.dropout_at_s = 3.0;
  sp.dropout_len_s = 0.3 - 1.0 / kRate;
  PoseFilterOptions o;
  o.playout_delay_s = 0.35;
  PoseFilter f(o);
  const auto st = run(f, tr, make_stream(tr, sp, 3), sp.duration_s);
  report("(a) roll 720, 0.3 s gap", st, f);
  EXPECT_EQ(st.nan, 0);
  EXPECT_LT(st.max_ang, 1e-6);
}

TEST(PoseFilter, TenGPullUpAndPush) {
  for (double n : {10.0, -10.0}) {
    const Truth tr = vertical_loop(n);
    StreamSpec sp;
    PoseFilter f;
    const auto st = run(f, tr, make_stream(tr, sp, 4), sp.duration_s);
    report(n > 0 ? "(b) +10 g loop, Hermite" : "(b) -10 g push, Hermite", st, f);
    EXPECT_EQ(st.nan, 0);
    EXPECT_LT(st.max_pos, 0.001);
    EXPECT_LT(st.max_ang, 1e-6);

    sp.velocity = false;  // linear position interpolation: chord error a h^2 / 8
    PoseFilter f2;
    const auto st2 = run(f2, tr, make_stream(tr, sp, 4), sp.duration_s);
    report(n > 0 ? "(b) +10 g loop, linear" : "(b) -10 g push, linear", st2, f2);
    EXPECT_EQ(st2.nan, 0);
    EXPECT_LT(st2.max_pos, 10 * kG / (kRate * kRate) / 8 * 1.01);
  }
}

TEST(PoseFilter, HeadingSweepThroughNorth) {
  const Truth tr = heading_sweep();
  for (bool rates : {true, false}) {
    StreamSpec sp;
    sp.rates = rates;
    sp.velocity = rates;
    sp.jitter_s = 0.01;
    PoseFilter f;
    double max_step = 0;
    bool have = false;
    glm::dquat prev;
    const auto st = run(f, tr, make_stream(tr, sp, 8), sp.duration_s, 0.5, nullptr, nullptr,
                        [&](double, const FilteredPose& p) {
                          if (have) max_step = std::max(max_step, ig::io::quat::angle_between(prev, p.attitude));
                          prev = p.attitude;
                          have = true;
                        });
    report(rates ? "(f) heading sweep via N" : "(f) heading sweep, no rates", st, f);
    std::printf("[filter] (f) largest frame-to-frame rotation %.4f deg (truth peak 0.55 deg/frame)\n",
                max_step * 180 / kPi);
    EXPECT_EQ(st.nan, 0);
    EXPECT_LT(st.max_ang, 0.01);
    EXPECT_LT(max_step * 180 / kPi, 1.0);  // no wrap-around flips
  }
}

TEST(PoseFilter, ReceiveTimeOnlyStream) {
  const Truth tr = manoeuvre();
  StreamSpec sp;
  sp.sender_time = false;
  sp.sequence = false;
  PoseFilter f;
  const auto st = run(f, tr, make_stream(tr, sp, 11), sp.duration_s, 0.5,
                      [](double s, double) { return s - kLatency; });
  report("receive time only", st, f);
  EXPECT_EQ(st.nan, 0);
  EXPECT_LT(st.max_pos, 0.05);
  EXPECT_NEAR(f.clock_offset_s(), 0.0, 1e-12);
}

TEST(PoseFilter, SequenceWrapAndRestart) {
  const Truth tr = manoeuvre();
  StreamSpec sp;
  sp.first_seq = 0xFFFFFF00u;  // wraps after 256 packets
  sp.reorder_prob = 0.05;
  sp.duplicate_prob = 0.05;
  PoseFilter f;
  const auto pk = make_stream(tr, sp, 12);
  const auto st = run(f, tr, pk, sp.duration_s);
  const Expected ex = expected_counts(pk);
  report("sequence wrap at 2^32", st, f);
  EXPECT_EQ(st.nan, 0);
  EXPECT_EQ(f.counters().duplicates, ex.duplicates);
  EXPECT_EQ(f.counters().out_of_order, ex.out_of_order);
  EXPECT_EQ(f.counters().sequence_resets, 0u);
  EXPECT_LT(st.max_pos, 0.05);

  // A sender restarting its counter (time continues): accepted, counted.
  PoseFilter g;
  PoseSample s;
  s.sequence = 5000;
  s.sender_time_s = 10.0;
  s.receive_time_s = 10.02;
  EXPECT_TRUE(g.push(s));
  s.sequence = 0;
  s.sender_time_s = 10.1;
  s.receive_time_s = 10.12;
  EXPECT_TRUE(g.push(s));
  EXPECT_EQ(g.counters().sequence_resets, 1u);
  s.sequence = 4999;  // stale relative to 0? no: 4999 is ahead of 0
  s.sender_time_s = 10.2;
  s.receive_time_s = 10.22;
  EXPECT_TRUE(g.push(s));
}

}  // namespace
