// The pose filter (docs/pose-filter.md): sender-clock estimation, packet
// ordering, interpolation and bounded extrapolation in one state machine.
// This file is its intake side (push: validation, clock offset, ordering);
// the output side (sample: interpolation, extrapolation) is
// pose_filter_sample.cpp.
#include "io/filter/pose_filter.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "io/filter/pose_filter_constants.h"
#include "io/filter/quat_util.h"

namespace ig::io {

using namespace pose_filter_detail;

namespace {

bool finite_sample(const PoseSample& s) {
  using quat::finite;
  if (!std::isfinite(s.receive_time_s)) return false;
  if (s.sender_time_s && !std::isfinite(*s.sender_time_s)) return false;
  if (!finite(s.position) || !finite(s.attitude)) return false;
  if (s.velocity_mps && !finite(*s.velocity_mps)) return false;
  if (s.body_rates_dps && !finite(*s.body_rates_dps)) return false;
  const double n2 = glm::dot(s.attitude, s.attitude);
  return n2 > 1e-12 && std::isfinite(n2);
}

}  // namespace

const char* latency_mode_name(LatencyMode m) {
  switch (m) {
    case LatencyMode::Smooth: return "smooth";
    case LatencyMode::Latest: return "latest";
    case LatencyMode::Synchronous: return "sync";
  }
  return "smooth";
}

std::optional<LatencyMode> parse_latency_mode(const std::string& text) {
  for (LatencyMode m : {LatencyMode::Smooth, LatencyMode::Latest, LatencyMode::Synchronous})
    if (text == latency_mode_name(m)) return m;
  return std::nullopt;
}

PoseFilter::PoseFilter(const PoseFilterOptions& options)
    : opt_(options), sender_clock_([&] {
        SenderClockOptions c = options.sender_clock;
        if (std::isfinite(options.nominal_interval_s) && options.nominal_interval_s > 0.0)
          c.nominal_interval_s = options.nominal_interval_s;
        return c;
      }()) {
  // Sanitize the knobs so that nothing below can divide by zero or go NaN.
  auto fin = [](double v, double dflt) { return std::isfinite(v) ? v : dflt; };
  opt_.playout_intervals = std::max(0.0, fin(opt_.playout_intervals, 2.0));
  opt_.jitter_factor = std::max(0.0, fin(opt_.jitter_factor, 1.0));
  opt_.min_playout_delay_s = std::max(0.0, fin(opt_.min_playout_delay_s, 0.0));
  opt_.max_playout_delay_s = std::max(opt_.min_playout_delay_s, fin(opt_.max_playout_delay_s, 0.1));
  opt_.playout_delay_s = fin(opt_.playout_delay_s, -1.0);
  if (!(opt_.nominal_interval_s > 0.0) || !std::isfinite(opt_.nominal_interval_s))
    opt_.nominal_interval_s = 1.0 / 60.0;
  if (!(opt_.offset_window_s > 0.0)) opt_.offset_window_s = 2.0;
  opt_.clock_slew = std::clamp(fin(opt_.clock_slew, 0.1), 0.0, 0.9);
  opt_.clock_snap_s = std::max(0.0, fin(opt_.clock_snap_s, 0.25));
  opt_.max_extrapolation_s = std::max(0.0, fin(opt_.max_extrapolation_s, 0.2));
  opt_.max_extrapolation_m = std::max(0.0, fin(opt_.max_extrapolation_m, 100.0));
  opt_.min_derive_step_fraction = std::max(0.0, fin(opt_.min_derive_step_fraction, 0.5));
  if (!(opt_.max_speed_mps > 0.0)) opt_.max_speed_mps = 1000.0;
  if (!(opt_.max_angular_rate_dps > 0.0)) opt_.max_angular_rate_dps = 1000.0;
  if (!(opt_.time_jump_s > 0.0)) opt_.time_jump_s = 1.0;
  if (!(opt_.clock_step_s > 0.0) || !std::isfinite(opt_.clock_step_s)) opt_.clock_step_s = 0.25;
  opt_.reorder_window = std::max<std::uint32_t>(1, std::min<std::uint32_t>(opt_.reorder_window, 0x7fffffffu));
  interval_ = opt_.nominal_interval_s;
  reset();
}

void PoseFilter::reset() {
  clear_stream();
  sender_clock_.reset();
  motion_.reset();
}

void PoseFilter::clear_stream() {
  head_ = count_ = 0;
  off_next_ = off_count_ = 0;
  offset_ = jitter_ = 0.0;
  seen_next_ = seen_count_ = 0;
  clock_init_ = false;
  above_ = false;
  have_output_ = false;
  last_tau_ = -std::numeric_limits<double>::infinity();
}

double PoseFilter::playout_delay_s() const {
  if (opt_.playout_delay_s >= 0.0) return opt_.playout_delay_s;
  // The interval part always counts (a 6 Hz host needs 170 ms to
  // interpolate at all); the clamp bounds what jitter may add.
  const double base = std::min(opt_.playout_intervals * interval_, 1.0);
  const double d = base + std::min(opt_.jitter_factor * jitter_, opt_.max_playout_delay_s);
  return std::max(d, opt_.min_playout_delay_s);
}

void PoseFilter::note_offset(double t, double recv) {
  off_t_[off_next_] = t;
  off_v_[off_next_] = recv - t;
  off_next_ = (off_next_ + 1) % kOffsetWindow;
  off_count_ = std::min(off_count_ + 1, kOffsetWindow);
  const double newest = at(count_ - 1).t;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int k = 0; k < off_count_; ++k) {
    if (off_t_[k] < newest - opt_.offset_window_s) continue;
    lo = std::min(lo, off_v_[k]);
    hi = std::max(hi, off_v_[k]);
  }
  if (!(lo <= hi)) lo = hi = recv - t;  // everything outside the window
  offset_ = lo;
  jitter_ = hi - lo;
}

void PoseFilter::note_seen(std::uint32_t seq, double t) {
  seen_seq_[seen_next_] = seq;
  seen_t_[seen_next_] = t;
  seen_next_ = (seen_next_ + 1) % kSeenRing;
  seen_count_ = std::min(seen_count_ + 1, kSeenRing);
}

bool PoseFilter::seen(std::uint32_t seq, double t) const {
  for (int k = 0; k < seen_count_; ++k) {
    if (stream_has_seq_ ? seen_seq_[k] == seq : seen_t_[k] == t) return true;
  }
  return false;
}

void PoseFilter::restart(const Entry& e) {
  clear_stream();
  at(0) = e;
  count_ = 1;
  newest_seq_ = e.seq;
  note_seen(e.seq, e.t);
  note_offset(e.t, e.recv);
  ++counters_.accepted;
}

void PoseFilter::append(const Entry& e) {
  const Entry& prev = at(count_ - 1);
  const double dt = e.t - prev.t;
  const double steps = stream_has_seq_ ? double(std::uint32_t(e.seq - prev.seq)) : 1.0;
  if (dt > 0.0 && steps >= 1.0 && dt < kMaxDiffGapS) {
    const double per = dt / steps;
    interval_ = interval_known_ ? interval_ + 0.1 * (per - interval_) : per;
    interval_known_ = true;
  }
  if (count_ == kCapacity) {  // drop the oldest
    head_ = (head_ + 1) % kCapacity;
    --count_;
  }
  at(count_) = e;
  ++count_;
  newest_seq_ = e.seq;
  note_seen(e.seq, e.t);
  note_offset(e.t, e.recv);
  ++counters_.accepted;
}

bool PoseFilter::insert_sorted(const Entry& e) {
  // Position of the first entry with t > e.t; equal times are not inserted.
  int k = count_;
  while (k > 0 && at(k - 1).t > e.t) --k;
  if (k > 0 && at(k - 1).t == e.t) return false;
  if (k == 0 && count_ == kCapacity) return false;  // older than all we keep
  if (count_ == kCapacity) {
    head_ = (head_ + 1) % kCapacity;
    --count_;
    --k;
  }
  for (int m = count_; m > k; --m) at(m) = at(m - 1);
  at(k) = e;
  ++count_;
  note_offset(e.t, e.recv);
  ++counters_.accepted;
  ++counters_.late_inserted;
  return true;
}

std::optional<std::uint32_t> PoseFilter::clock_sequence(const PoseSample& s) {
  if (clock_counter_unit(s) == CounterUnit::SenderPackets) return s.sequence;
  return motion_.next(s.position, *s.velocity_mps, s.receive_time_s, sender_clock_.period_s());
}

CounterUnit PoseFilter::clock_counter_unit(const PoseSample& s) {
  return !s.sequence && s.velocity_mps ? CounterUnit::ClockPeriods : CounterUnit::SenderPackets;
}

bool PoseFilter::push(const PoseSample& s) {
  ++counters_.received;
  if (!finite_sample(s)) {
    ++counters_.non_finite;
    return false;
  }
  Entry e;
  // Without a sender clock: the de-jittered estimate of when it was sent.
  if (s.sender_time_s) e.t = *s.sender_time_s;
  else if (opt_.dejitter_receive_times) e.t = sender_clock_.stamp(s.receive_time_s, clock_sequence(s), clock_counter_unit(s));
  else e.t = s.receive_time_s;
  e.recv = s.receive_time_s;
  e.seq = s.sequence.value_or(0);
  e.pos = s.position;
  e.att = glm::normalize(s.attitude);
  if (s.velocity_mps) {
    e.vel = *s.velocity_mps;
    e.has_vel = true;
  }
  if (s.body_rates_dps) {
    const glm::dvec3 r = *s.body_rates_dps * kDegToRad;  // (p, q, r)
    e.omega = glm::dvec3(r[1], r[0], -r[2]);               // body (x, y, z)
    e.has_omega = true;
  }

  const bool has_sender = s.sender_time_s.has_value();
  const bool has_seq = s.sequence.has_value();
  if (count_ == 0) {
    stream_has_sender_ = has_sender;
    stream_has_seq_ = has_seq;
    restart(e);
    return true;
  }
  if (has_sender != stream_has_sender_ || has_seq != stream_has_seq_) {
    // The time base or numbering changed: a different sender. Start over.
    ++counters_.time_jumps;
    if (!has_sender && opt_.dejitter_receive_times) {
      sender_clock_.reset();
      motion_.reset();
      e.t = sender_clock_.stamp(s.receive_time_s, clock_sequence(s), clock_counter_unit(s));
    }
    stream_has_sender_ = has_sender;
    stream_has_seq_ = has_seq;
    restart(e);
    return true;
  }

  const Entry& newest = at(count_ - 1);
  // Keep neighbouring quaternions in one hemisphere (slerp, differencing).
  if (glm::dot(newest.att, e.att) < 0.0) e.att = -e.att;

  bool stale = false;
  bool seq_restart = false;
  if (stream_has_seq_) {
    const std::int32_t d = static_cast<std::int32_t>(e.seq - newest_seq_);  // wraps correctly
    if (d <= 0 && d > -static_cast<std::int64_t>(opt_.reorder_window)) {
      stale = true;
    } else if (d <= 0) {
      seq_restart = true;
    }
  } else if (e.t <= newest.t) {
    stale = true;
  }
  if (stale && seen(e.seq, e.t)) {
    ++counters_.duplicates;
    return false;
  }
  // Sender clock jump: sender time off from the progression expected from the
  // receive clock. (Receive-time-only streams never trigger this.)
  if (!stale || !stream_has_seq_) {
    const double expected = newest.t + (e.recv - newest.recv);
    if (std::fabs(e.t - expected) > opt_.time_jump_s) {
      ++counters_.time_jumps;
      restart(e);
      return true;
    }
  }
  // A newer packet (by sequence number) stamped earlier than the newest: the
  // sender's clock stepped back by less than time_jump_s. Appending it would
  // unsort the buffer; start a fresh stream as for any clock jump.
  if (!stale && !seq_restart && e.t < newest.t) {
    ++counters_.time_jumps;
    restart(e);
    return true;
  }
  // Smaller steps of either clock: an offset change that delay cannot
  // explain (see PoseFilterOptions::clock_step_s).
  if (!stale) {
    const double off = e.recv - e.t;
    bool step = off < offset_ - opt_.clock_step_s;
    if (off > offset_ + opt_.clock_step_s) {
      if (!above_) above_since_ = e.t;
      above_ = true;
      step = step || e.t - above_since_ >= opt_.clock_step_s;
    } else {
      above_ = false;
    }
    if (step) {
      ++counters_.time_jumps;
      restart(e);
      return true;
    }
  }
  if (seq_restart) {
    if (e.t <= newest.t) {  // numbering restarted but time did not advance: stale
      stale = true;
    } else {
      ++counters_.sequence_resets;
      append(e);
      return true;
    }
  }
  if (stale) {
    ++counters_.out_of_order;
    note_seen(e.seq, e.t);
    if (opt_.insert_late_packets && e.t > last_tau_) return insert_sorted(e);
    return false;
  }
  if (e.t == newest.t) {
    // A newer sequence number with the same sender time: last writer wins.
    at(count_ - 1) = e;
    newest_seq_ = e.seq;
    note_seen(e.seq, e.t);
    ++counters_.accepted;
    return true;
  }
  append(e);
  return true;
}

}  // namespace ig::io
