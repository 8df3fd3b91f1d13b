#pragma once
// Shared fixtures of the pose filter tests (pose_filter_test.cpp,
// pose_filter_impairments_test.cpp; header only): analytic truth
// trajectories, a 60 Hz packet stream with impairments, and the run that
// samples the filter at 60 Hz and measures its error against the truth.

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

#include "io/filter/pose_filter.h"
#include "io/filter/quat_util.h"
#include "io/pose.h"

namespace pose_filter_test {

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

inline glm::dquat axis_q(double deg, int axis) {
  glm::dvec3 v(0.0);
  v[axis] = deg * kPi / 180.0;
  return ig::io::quat::exp_rotvec(v);
}

// World velocity and body rates (p, q, r) in deg/s by central differences.
inline glm::dvec3 truth_vel(const Truth& f, double t) {
  const double e = 1e-4;
  return (f(t + e).pos - f(t - e).pos) / (2 * e);
}
inline glm::dvec3 truth_rates_dps(const Truth& f, double t) {
  const double e = 1e-4;
  const glm::dvec3 w = ig::io::quat::log_rotvec(glm::conjugate(f(t - e).att) * f(t + e).att) / (2 * e);
  return glm::dvec3(w.y, w.x, -w.z) * (180.0 / kPi);
}

// ---- Trajectories -------------------------------------------------------
inline Truth roll_720() {  // 720 deg/s roll in straight flight at 120 m/s, heading 30
  return [](double t) {
    const double h = 30.0 * kPi / 180.0;
    return TruthState{{120 * std::sin(h) * t, 120 * std::cos(h) * t, 1500.0},
                      attitude_from_hpr({30.0, 0.0, 720.0 * t})};
  };
}
inline Truth vertical_loop(double n_g) {  // constant n_g normal load at 200 m/s; negative = push
  return [n_g](double t) {
    const double v = 200.0, w = n_g * kG / v;  // rad/s
    const double r = v / w;
    const double a = w * t;
    return TruthState{{0.0, r * std::sin(a), 2000.0 + r * (1 - std::cos(a))},
                      axis_q(a * 180.0 / kPi, 0)};
  };
}
inline Truth heading_sweep() {  // heading 340 -> 20 -> 340 ..., 31.4 deg/s peak
  return [](double t) {
    const double hd = 20.0 * std::sin(2 * kPi * t / 4.0);
    return TruthState{{0.0, 100 * t, 800.0}, attitude_from_hpr({hd, 5.0, 10.0})};
  };
}
inline Truth manoeuvre() {  // 2 g level turn with roll and pitch oscillations
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

inline std::vector<Packet> make_stream(const Truth& f, const StreamSpec& sp, std::uint32_t seed) {
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
inline Expected expected_counts(const std::vector<Packet>& pk) {
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

inline bool finite_pose(const FilteredPose& p) {
  return ig::io::quat::finite(p.position) && ig::io::quat::finite(p.attitude) && std::isfinite(p.age_s) &&
         std::isfinite(p.sample_time_s) && std::abs(glm::length(p.attitude) - 1.0) < 1e-9;
}

// Feed the stream, sample at 60 Hz (phase-shifted from the sender), compare.
// skip(t): true for render times excluded from the error statistics.
inline RunStats run(PoseFilter& f, const Truth& truth, const std::vector<Packet>& pk, double duration,
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

inline void report(const char* name, const RunStats& s, const PoseFilter& f) {
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

// The manoeuvre sent as `spec` describes (make_stream with `seed`) through a
// default filter, run after `warmup` and reported as `name`.
struct ImpairedRun {
  ImpairedRun(const StreamSpec& s, std::uint32_t seed, const char* name, double warmup = 0.5)
      : spec(s), packets(make_stream(truth, spec, seed)), stats(run(filter, truth, packets, spec.duration_s, warmup)) {
    report(name, stats, filter);
  }

  Truth truth = manoeuvre();
  StreamSpec spec;
  std::vector<Packet> packets;
  PoseFilter filter;
  RunStats stats;
};

inline void expect_consistent(const PoseFilter& f) {
  const auto& c = f.counters();
  EXPECT_EQ(c.received, c.accepted + c.duplicates + (c.out_of_order - c.late_inserted) + c.non_finite);
  EXPECT_LE(c.late_inserted, c.out_of_order);
}

}  // namespace pose_filter_test
