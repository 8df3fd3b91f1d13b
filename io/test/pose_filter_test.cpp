// PoseFilter (io/filter/pose_filter.h) against analytic truth trajectories
// sent as a 60 Hz packet stream with loss, jitter, reordering, duplicates,
// clock jumps and dropouts, sampled by a 60 Hz render clock. The printed
// "[filter]" lines are the measured error table of docs/pose-filter.md.
// Long because each impairment (loss, jitter, reordering, duplicates, clock
// jumps, dropouts) gets its own trajectory and error check against one truth.
#include "io/filter/pose_filter.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "io/filter/quat_util.h"
#include "io/pose.h"

namespace {

using namespace ig::io;

constexpr double kPi = 3.14159265358979323846;
constexpr double kG = 9.80665;
constexpr double kRate = 60.0;      // packets and frames per second
constexpr double kLatency = 0.020;  // fixed network latency, s

// Uniform [0, 1) from raw mt19937 output (distributions are not portable).
struct Rng {
  std::mt19937 eng;
  explicit Rng(std::uint32_t seed) : eng(seed) {}
  double u() { return ((std::uint64_t(eng()) << 21) ^ (eng() >> 11)) * (1.0 / 9007199254740992.0); }
};

struct TruthState {
  glm::dvec3 pos;
  glm::dquat att;
};
using Truth = std::function<TruthState(double)>;

glm::dquat axis_q(double deg, int axis) {
  glm::dvec3 v(0.0);
  v[axis] = deg * kPi / 180.0;
  return ig::io::quat::exp_rotvec(v);
}

// World velocity and body rates (p, q, r) in deg/s by central differences.
glm::dvec3 truth_vel(const Truth& f, double t) {
  const double e = 1e-4;
  return (f(t + e).pos - f(t - e).pos) / (2 * e);
}
glm::dvec3 truth_rates_dps(const Truth& f, double t) {
  const double e = 1e-4;
  const glm::dvec3 w = ig::io::quat::log_rotvec(glm::conjugate(f(t - e).att) * f(t + e).att) / (2 * e);
  return glm::dvec3(w.y, w.x, -w.z) * (180.0 / kPi);
}

// ---- Trajectories -------------------------------------------------------
Truth roll_720() {  // 720 deg/s roll in straight flight at 120 m/s, heading 30
  return [](double t) {
    const double h = 30.0 * kPi / 180.0;
    return TruthState{{120 * std::sin(h) * t, 120 * std::cos(h) * t, 1500.0},
                      attitude_from_hpr({30.0, 0.0, 720.0 * t})};
  };
}
Truth vertical_loop(double n_g) {  // constant n_g normal load at 200 m/s; negative = push
  return [n_g](double t) {
    const double v = 200.0, w = n_g * kG / v;  // rad/s
    const double r = v / w;
    const double a = w * t;
    return TruthState{{0.0, r * std::sin(a), 2000.0 + r * (1 - std::cos(a))},
                      axis_q(a * 180.0 / kPi, 0)};
  };
}
Truth heading_sweep() {  // heading 340 -> 20 -> 340 ..., 31.4 deg/s peak
  return [](double t) {
    const double hd = 20.0 * std::sin(2 * kPi * t / 4.0);
    return TruthState{{0.0, 100 * t, 800.0}, attitude_from_hpr({hd, 5.0, 10.0})};
  };
}
Truth manoeuvre() {  // 2 g level turn with roll and pitch oscillations
  return [](double t) {
    const double v = 150.0, r = v * v / (2 * kG), w = v / r;
    const double hd = w * t * 180.0 / kPi;
    return TruthState{{r * (1 - std::cos(w * t)), r * std::sin(w * t), 1000 + 30 * std::sin(1.3 * t)},
                      attitude_from_hpr({hd, 5 * std::sin(1.3 * t), 60 + 20 * std::sin(2.1 * t)})};
  };
}

// ---- Packet stream --------------------------------------------------------
struct StreamSpec {
  double duration_s = 8.0;
  bool velocity = true;
  bool rates = true;
  bool sender_time = true;
  bool sequence = true;
  std::uint32_t first_seq = 1;
  double jitter_s = 0.0;                 // uniform [0, jitter) added to receive time
  double loss_burst_prob = 0.0;          // 50 % loss inside bursts
  double burst_period_s = 2.0, burst_len_s = 0.6;
  double reorder_prob = 0.0;             // swap with the next packet
  double duplicate_prob = 0.0;           // deliver a second copy a little later
  double nonfinite_prob = 0.0;           // also deliver a NaN-corrupted copy
  double dropout_at_s = -1, dropout_len_s = 0.0;
  std::vector<std::pair<double, double>> clock_steps;  // (at true t, sender clock offset after)
};

struct Packet {
  PoseSample s;
  double true_t;
  bool injected_dup = false, injected_nan = false;
};

std::vector<Packet> make_stream(const Truth& f, const StreamSpec& sp, std::uint32_t seed) {
  Rng rng(seed);
  std::vector<Packet> out;
  const int n = int(sp.duration_s * kRate);
  for (int k = 0; k < n; ++k) {
    const double t = k / kRate;
    const double u_loss = rng.u(), u_jit = rng.u(), u_reo = rng.u(), u_dup = rng.u(), u_nan = rng.u();
    const bool in_burst = std::fmod(t, sp.burst_period_s) >= sp.burst_period_s - sp.burst_len_s;
    if (sp.loss_burst_prob > 0 && in_burst && u_loss < 0.5) continue;
    if (sp.dropout_at_s >= 0 && t >= sp.dropout_at_s && t < sp.dropout_at_s + sp.dropout_len_s) continue;
    double clock = 0.0;
    for (auto [at, off] : sp.clock_steps)
      if (t >= at) clock = off;
    Packet p;
    p.true_t = t;
    const TruthState ts = f(t);
    p.s.receive_time_s = t + kLatency + sp.jitter_s * u_jit;
    if (sp.sender_time) p.s.sender_time_s = t + clock;
    if (sp.sequence) p.s.sequence = sp.first_seq + std::uint32_t(k);
    p.s.position = ts.pos;
    p.s.attitude = ts.att;
    if (sp.velocity) p.s.velocity_mps = truth_vel(f, t);
    if (sp.rates) p.s.body_rates_dps = truth_rates_dps(f, t);
    p.s.source = "test";
    out.push_back(p);
    if (u_dup < sp.duplicate_prob) {
      Packet d = p;
      d.injected_dup = true;
      d.s.receive_time_s += 0.001 + 0.05 * rng.u();
      out.push_back(d);
    }
    if (u_nan < sp.nonfinite_prob) {
      Packet d = p;
      d.injected_nan = true;
      d.s.position.x = std::nan("");
      out.push_back(d);
    }
    if (u_reo < sp.reorder_prob) {
      // Arrive after the next packet: 1.5 intervals late.
      out.back().s.receive_time_s += 1.5 / kRate;
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const Packet& a, const Packet& b) {
    return a.s.receive_time_s < b.s.receive_time_s;
  });
  return out;
}

// What the filter should count, from the delivery order.
struct Expected {
  std::uint64_t duplicates = 0, out_of_order = 0, non_finite = 0;
};
Expected expected_counts(const std::vector<Packet>& pk) {
  Expected e;
  std::set<std::uint32_t> seen;
  bool have = false;
  std::uint32_t newest = 0;
  for (const auto& p : pk) {
    if (p.injected_nan) {
      ++e.non_finite;
      continue;
    }
    const std::uint32_t s = *p.s.sequence;
    const bool older = have && std::int32_t(s - newest) <= 0;
    if (older && seen.count(s)) {
      ++e.duplicates;
    } else if (older) {
      ++e.out_of_order;
      seen.insert(s);
    } else {
      seen.insert(s);
      newest = s;
      have = true;
    }
  }
  return e;
}

struct RunStats {
  double max_pos = 0, max_ang = 0, sum_pos2 = 0, sum_ang2 = 0;
  double max_pos_nominal = 0, max_ang_nominal = 0;  // vs truth at now - latency - delay
  double max_timeline = 0;                          // |sample time - (now - latency - delay)|
  int n = 0, nan = 0;
  int modes[3] = {0, 0, 0};
  double rms_pos() const { return n ? std::sqrt(sum_pos2 / n) : 0; }
  double rms_ang() const { return n ? std::sqrt(sum_ang2 / n) : 0; }
};

bool finite_pose(const FilteredPose& p) {
  return ig::io::quat::finite(p.position) && ig::io::quat::finite(p.attitude) && std::isfinite(p.age_s) &&
         std::isfinite(p.sample_time_s) && std::abs(glm::length(p.attitude) - 1.0) < 1e-9;
}

// Feed the stream, sample at 60 Hz (phase-shifted from the sender), compare.
// skip(t): true for render times excluded from the error statistics.
RunStats run(PoseFilter& f, const Truth& truth, const std::vector<Packet>& pk, double duration,
             double warmup = 0.5, std::function<double(double, double)> sender_to_true = nullptr,
             std::function<bool(double)> skip = nullptr,
             std::function<void(double, const FilteredPose&)> each = nullptr) {
  RunStats st;
  std::size_t next = 0;
  for (int k = 0;; ++k) {
    const double now = 0.0037 + k / kRate;
    if (now > duration + 0.3) break;
    while (next < pk.size() && pk[next].s.receive_time_s <= now) f.push(pk[next++].s);
    const auto out = f.sample(now);
    if (!out) continue;
    if (!finite_pose(*out)) {
      ++st.nan;
      continue;
    }
    if (each) each(now, *out);
    if (now < warmup || (skip && skip(now))) continue;
    const double t_true = sender_to_true ? sender_to_true(out->sample_time_s, now) : out->sample_time_s;
    const double t_nom = now - kLatency - out->playout_delay_s;
    if (std::max(t_true, t_nom) > duration - 1.0 / kRate) continue;  // past the end of the stream
    const TruthState ts = truth(t_true);
    const double ep = glm::length(out->position - ts.pos);
    const double ea = ig::io::quat::angle_between(out->attitude, ts.att) * 180.0 / kPi;
    const TruthState tn = truth(t_nom);
    st.max_pos = std::max(st.max_pos, ep);
    st.max_ang = std::max(st.max_ang, ea);
    st.sum_pos2 += ep * ep;
    st.sum_ang2 += ea * ea;
    st.max_pos_nominal = std::max(st.max_pos_nominal, glm::length(out->position - tn.pos));
    st.max_ang_nominal =
        std::max(st.max_ang_nominal, ig::io::quat::angle_between(out->attitude, tn.att) * 180.0 / kPi);
    st.max_timeline = std::max(st.max_timeline, std::fabs(t_true - t_nom));
    ++st.n;
    ++st.modes[out->mode];
  }
  return st;
}

void report(const char* name, const RunStats& s, const PoseFilter& f) {
  const auto& c = f.counters();
  std::printf("[filter] %-28s pos max %8.4f m rms %7.4f | att max %7.4f deg rms %7.4f | nominal pos %8.4f m att "
              "%7.4f deg | timeline %6.2f ms | interp/extrap/hold %d/%d/%d | delay %.1f ms\n",
              name, s.max_pos, s.rms_pos(), s.max_ang, s.rms_ang(), s.max_pos_nominal, s.max_ang_nominal,
              s.max_timeline * 1e3, s.modes[0], s.modes[1], s.modes[2], f.playout_delay_s() * 1e3);
  std::printf("[filter] %-28s counters: received %llu accepted %llu dup %llu ooo %llu late-inserted %llu "
              "nonfinite %llu jumps %llu extrap %llu holds %llu\n",
              name, (unsigned long long)c.received, (unsigned long long)c.accepted,
              (unsigned long long)c.duplicates, (unsigned long long)c.out_of_order,
              (unsigned long long)c.late_inserted, (unsigned long long)c.non_finite,
              (unsigned long long)c.time_jumps, (unsigned long long)c.extrapolations,
              (unsigned long long)c.holds);
}

void expect_consistent(const PoseFilter& f) {
  const auto& c = f.counters();
  EXPECT_EQ(c.received, c.accepted + c.duplicates + (c.out_of_order - c.late_inserted) + c.non_finite);
  EXPECT_LE(c.late_inserted, c.out_of_order);
}

// ---- Tests ------------------------------------------------------------------

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

TEST(PoseFilter, LossBursts50Percent) {
  const Truth tr = manoeuvre();
  StreamSpec sp;
  sp.loss_burst_prob = 1.0;
  PoseFilter f;
  const auto pk = make_stream(tr, sp, 5);
  const auto st = run(f, tr, pk, sp.duration_s);
  report("(c) 50% loss bursts", st, f);
  EXPECT_EQ(st.nan, 0);
  // Gaps of up to 5 intervals exceed the 2-interval delay: short extrapolations.
  EXPECT_LT(st.max_pos, 0.2);
  EXPECT_LT(st.max_ang, 0.2);
  EXPECT_GT(f.counters().extrapolations, 20u);
  EXPECT_EQ(f.counters().accepted, pk.size());
  EXPECT_NEAR(f.packet_interval_s(), 1.0 / kRate, 1e-6);  // loss does not inflate it
}

TEST(PoseFilter, Jitter100ms) {
  const Truth tr = manoeuvre();
  StreamSpec sp;
  sp.jitter_s = 0.100;
  PoseFilter f;
  const auto pk = make_stream(tr, sp, 6);
  const auto st = run(f, tr, pk, sp.duration_s, 1.0);
  report("(d) 100 ms jitter", st, f);
  EXPECT_EQ(st.nan, 0);
  EXPECT_LT(st.max_pos, 1.0);
  EXPECT_LT(st.max_ang, 1.0);
  EXPECT_LT(st.max_timeline, 0.010);  // offset estimate: min of ~0.1 s uniform jitter
  // One interval + the jitter allowance (~100 ms of jitter, clamped at 100 ms).
  EXPECT_NEAR(f.playout_delay_s(), f.packet_interval_s() + std::min(f.jitter_s(), 0.100), 1e-9);
  const Expected ex = expected_counts(pk);
  EXPECT_EQ(f.counters().out_of_order, ex.out_of_order);
  EXPECT_GT(f.counters().late_inserted, ex.out_of_order * 9 / 10);
  expect_consistent(f);

  // Strict mode (drop every out-of-order packet) for comparison.
  PoseFilterOptions o;
  o.insert_late_packets = false;
  PoseFilter g(o);
  const auto sg = run(g, tr, pk, sp.duration_s, 1.0);
  report("(d) 100 ms jitter, strict drop", sg, g);
  EXPECT_EQ(sg.nan, 0);
  EXPECT_EQ(g.counters().late_inserted, 0u);
  EXPECT_EQ(g.counters().out_of_order, ex.out_of_order);
  expect_consistent(g);
}

TEST(PoseFilter, ReorderingDuplicatesAndNonFinite) {
  const Truth tr = manoeuvre();
  StreamSpec sp;
  sp.reorder_prob = 0.1;
  sp.duplicate_prob = 0.1;
  sp.nonfinite_prob = 0.02;
  sp.jitter_s = 0.004;
  PoseFilter f;
  const auto pk = make_stream(tr, sp, 7);
  const auto st = run(f, tr, pk, sp.duration_s);
  report("(e) reorder 10% dup 10%", st, f);
  const Expected ex = expected_counts(pk);
  std::printf("[filter] (e) injected: dup %llu ooo %llu nonfinite %llu\n", (unsigned long long)ex.duplicates,
              (unsigned long long)ex.out_of_order, (unsigned long long)ex.non_finite);
  EXPECT_EQ(st.nan, 0);
  EXPECT_GT(ex.duplicates, 20u);
  EXPECT_GT(ex.out_of_order, 20u);
  EXPECT_EQ(f.counters().duplicates, ex.duplicates);
  EXPECT_EQ(f.counters().out_of_order, ex.out_of_order);
  EXPECT_EQ(f.counters().non_finite, ex.non_finite);
  EXPECT_EQ(f.counters().time_jumps, 0u);
  expect_consistent(f);
  EXPECT_LT(st.max_pos, 0.05);
  EXPECT_LT(st.max_ang, 0.1);
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
