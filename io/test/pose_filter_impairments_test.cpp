// PoseFilter (io/filter/pose_filter.h) under network and clock impairments:
// loss, jitter, reordering, duplicates, clock jumps and dropouts, each its own
// stream against one analytic truth. The printed "[filter]" lines are part of
// the measured error table of docs/pose-filter.md.
#include "io/filter/pose_filter.h"

#include <gtest/gtest.h>

#include "io/test/pose_filter_test_support.h"

namespace {

using namespace pose_filter_test;

TEST(PoseFilter, LossBursts50Percent) {
  StreamSpec sp;
  sp.loss_burst_prob = 1.0;
  const ImpairedRun r(sp, 5, "(c) 50% loss bursts");
  EXPECT_EQ(r.stats.nan, 0);
  // Gaps of up to 5 intervals exceed the 2-interval delay: short extrapolations.
  EXPECT_LT(r.stats.max_pos, 0.2);
  EXPECT_LT(r.stats.max_ang, 0.2);
  EXPECT_GT(r.filter.counters().extrapolations, 20u);
  EXPECT_EQ(r.filter.counters().accepted, r.packets.size());
  EXPECT_NEAR(r.filter.packet_interval_s(), 1.0 / kRate, 1e-6);  // loss does not inflate it
}

TEST(PoseFilter, Jitter100ms) {
  StreamSpec sp;
  sp.jitter_s = 0.100;
  const ImpairedRun r(sp, 6, "(d) 100 ms jitter", 1.0);
  const PoseFilter& f = r.filter;
  EXPECT_EQ(r.stats.nan, 0);
  EXPECT_LT(r.stats.max_pos, 1.0);
  EXPECT_LT(r.stats.max_ang, 1.0);
  EXPECT_LT(r.stats.max_timeline, 0.010);  // offset estimate: min of ~0.1 s uniform jitter
  // One interval + the jitter allowance (~100 ms of jitter, clamped at 100 ms).
  EXPECT_NEAR(f.playout_delay_s(), f.packet_interval_s() + std::min(f.jitter_s(), 0.100), 1e-9);
  const Expected ex = expected_counts(r.packets);
  EXPECT_EQ(f.counters().out_of_order, ex.out_of_order);
  EXPECT_GT(f.counters().late_inserted, ex.out_of_order * 9 / 10);
  expect_consistent(f);

  // Strict mode (drop every out-of-order packet) for comparison.
  PoseFilterOptions o;
  o.insert_late_packets = false;
  PoseFilter g(o);
  const auto sg = run(g, r.truth, r.packets, r.spec.duration_s, 1.0);
  report("(d) 100 ms jitter, strict drop", sg, g);
  EXPECT_EQ(sg.nan, 0);
  EXPECT_EQ(g.counters().late_inserted, 0u);
  EXPECT_EQ(g.counters().out_of_order, ex.out_of_order);
  expect_consistent(g);
}

TEST(PoseFilter, ReorderingDuplicatesAndNonFinite) {
  StreamSpec sp;
  sp.reorder_prob = 0.1;
  sp.duplicate_prob = 0.1;
  sp.nonfinite_prob = 0.02;
  sp.jitter_s = 0.004;
  const ImpairedRun r(sp, 7, "(e) reorder 10% dup 10%");
  const PoseFilter& f = r.filter;
  const Expected ex = expected_counts(r.packets);
  std::printf("[filter] (e) injected: dup %llu ooo %llu nonfinite %llu\n", (unsigned long long)ex.duplicates,
              (unsigned long long)ex.out_of_order, (unsigned long long)ex.non_finite);
  EXPECT_EQ(r.stats.nan, 0);
  EXPECT_GT(ex.duplicates, 20u);
  EXPECT_GT(ex.out_of_order, 20u);
  EXPECT_EQ(f.counters().duplicates, ex.duplicates);
  EXPECT_EQ(f.counters().out_of_order, ex.out_of_order);
  EXPECT_EQ(f.counters().non_finite, ex.non_finite);
  EXPECT_EQ(f.counters().time_jumps, 0u);
  expect_consistent(f);
  EXPECT_LT(r.stats.max_pos, 0.05);
  EXPECT_LT(r.stats.max_ang, 0.1);
}

TEST(PoseFilter, HostTimeJumpsBackAndForward) {
  const Truth tr = manoeuvre();
  StreamSpec sp;
  sp.clock_steps = {{3.0, -5.0}, {6.0, -2.0}};  // back 5 s at t=3, forward 3 s at t=6
  sp.duration_s = 9.0;
  PoseFilter f;
  const auto pk = make_stream(tr, sp, 9);
  auto near_jump = [](double now) {
    return (now >= 3.0 && now < 3.3) || (now >= 6.0 && now < 6.3);
  };
  // Sender time -> true time: the clock segment that fits the render time.
  auto to_true = [](double s, double now) {
    double best = s;
    for (double c : {0.0, -5.0, -2.0})
      if (std::fabs(s - c - (now - 0.06)) < std::fabs(best - (now - 0.06))) best = s - c;
    return best;
  };
  double max_transient = 0;
  const auto st = run(f, tr, pk, sp.duration_s, 0.5,
                      to_true, near_jump,
                      [&](double now, const FilteredPose& p) {
                        const TruthState t = tr(now - kLatency - p.playout_delay_s);
                        if (now > 0.5 && now < sp.duration_s - 0.1) max_transient = std::max(max_transient, glm::length(p.position - t.pos));
                      });
  report("(g) clock jump -5 s, +3 s", st, f);
  std::printf("[filter] (g) max position error including the 0.3 s after each jump: %.3f m\n", max_transient);
  EXPECT_EQ(st.nan, 0);
  EXPECT_EQ(f.counters().time_jumps, 2u);
  EXPECT_LT(st.max_pos_nominal, 1.0);
  EXPECT_LT(st.max_ang_nominal, 1.0);
  // Right after a reset the filter holds the first new sample for one delay.
  EXPECT_LT(max_transient, 150.0 * 0.15);
}

TEST(PoseFilter, SmallClockStepsResetInsteadOfMixingTimelines) {
  // Steps below time_jump_s (1 s): the sender clock back 0.5 s (a newer
  // sequence number stamped earlier; appending it would unsort the buffer)
  // and forward 0.5 s (the offset drops below its floor). Each resets.
  const Truth tr = manoeuvre();
  StreamSpec sp;
  sp.duration_s = 6.0;
  sp.clock_steps = {{2.0, -0.5}, {4.0, 0.0}};
  PoseFilter f;
  const auto pk = make_stream(tr, sp, 12);
  auto near_step = [](double now) { return (now >= 2.0 && now < 2.3) || (now >= 4.0 && now < 4.3); };
  auto to_true = [](double s, double now) {
    double best = s;
    for (double c : {0.0, -0.5})
      if (std::fabs(s - c - (now - 0.06)) < std::fabs(best - (now - 0.06))) best = s - c;
    return best;
  };
  double worst_step = 0.0;
  glm::dvec3 prev{0.0};
  bool have = false;
  const auto st = run(f, tr, pk, sp.duration_s, 0.5, to_true, near_step, [&](double, const FilteredPose& p) {
    if (have) worst_step = std::max(worst_step, glm::length(p.position - prev));
    prev = p.position;
    have = true;
  });
  report("clock steps -0.5 s, +0.5 s", st, f);
  std::printf("[filter] clock steps -0.5/+0.5 s: largest frame-to-frame step %.2f m (2.5 m of motion per frame)\n",
              worst_step);
  EXPECT_EQ(st.nan, 0);
  EXPECT_EQ(f.counters().time_jumps, 2u);
  EXPECT_LT(st.max_pos, 1e-3);
  EXPECT_LT(worst_step, 150.0 * 0.1);  // at most a playout delay's worth at a reset, never a replay
}

TEST(PoseFilter, Dropout200msAnd500ms) {
  const Truth tr = manoeuvre();
  for (double len : {0.2, 0.5}) {
    StreamSpec sp;
    sp.dropout_at_s = 4.0;
    sp.dropout_len_s = len;
    PoseFilter f;
    const auto pk = make_stream(tr, sp, 10);
    // The last packet before the dropout.
    const Packet* last = nullptr;
    for (const auto& p : pk)
      if (p.true_t < 4.0) last = &p;
    double max_overshoot = 0, max_hold_move = 0;
    bool holding = false;
    glm::dvec3 hold_pos{0.0};
    const auto st = run(f, tr, pk, sp.duration_s, 0.5, nullptr, nullptr, [&](double now, const FilteredPose& p) {
      if (p.mode == FilteredPose::Interpolating) {
        holding = false;
        return;
      }
      if (now < 4.0 || now > 4.0 + len + 0.3) return;  // the dropout, not start/end of stream
      // Extrapolated or held: never beyond max_extrapolation_s * |v| of the last sample.
      const double d = glm::length(p.position - last->s.position);
      max_overshoot = std::max(max_overshoot, d / (glm::length(*last->s.velocity_mps) * 0.2));
      if (p.mode == FilteredPose::Holding) {
        if (holding) max_hold_move = std::max(max_hold_move, glm::length(p.position - hold_pos));
        hold_pos = p.position;
        holding = true;
      }
    });
    char name[64];
    std::snprintf(name, sizeof name, "(h) %.0f ms dropout", len * 1e3);
    report(name, st, f);
    std::printf("[filter] (h) %.0f ms: extrapolated distance / (0.2 s * |v|) max %.4f, hold drift %.3g m\n",
                len * 1e3, max_overshoot, max_hold_move);
    EXPECT_EQ(st.nan, 0);
    EXPECT_GT(f.counters().extrapolations, 0u);
    EXPECT_LE(max_overshoot, 1.0 + 1e-9);
    EXPECT_EQ(max_hold_move, 0.0);
    if (len < 0.3) {
      EXPECT_EQ(st.modes[2], 0);  // 200 ms never reaches the 200 ms hold limit
      EXPECT_LT(st.max_pos, 1.5);  // measured 0.67 m: constant-velocity extrapolation in a 2 g turn
      EXPECT_LT(st.max_ang, 2.0);  // measured 1.0 deg
    } else {
      EXPECT_GT(st.modes[2], 0);
    }
  }
}

}  // namespace
