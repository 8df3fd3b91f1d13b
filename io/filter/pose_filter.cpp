// The pose filter (docs/pose-filter.md): sender-clock estimation, packet
// ordering, interpolation and bounded extrapolation in one state machine.
// Over 500 lines because those steps share one per-stream state; splitting
// them would spread that state across files.
#include "io/filter/pose_filter.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "io/filter/quat_util.h"

namespace ig::io {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegToRad = kPi / 180.0;
// Consecutive samples further apart than this are not differenced for
// extrapolation rates or used for the packet interval estimate.
constexpr double kMaxDiffGapS = 0.5;

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

bool PoseFilter::push(const PoseSample& s) {
  ++counters_.received;
  if (!finite_sample(s)) {
    ++counters_.non_finite;
    return false;
  }
  Entry e;
  // Without a sender clock: the de-jittered estimate of when it was sent.
  if (s.sender_time_s) e.t = *s.sender_time_s;
  else if (opt_.dejitter_receive_times) e.t = sender_clock_.stamp(s.receive_time_s, s.sequence);
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
      e.t = sender_clock_.stamp(s.receive_time_s, s.sequence);
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

glm::dvec3 PoseFilter::clamp_velocity(glm::dvec3 v) {
  const double len = glm::length(v);
  if (len <= opt_.max_speed_mps) return v;
  ++counters_.clamped_rates;
  return v * (opt_.max_speed_mps / len);
}

glm::dvec3 PoseFilter::clamp_omega(glm::dvec3 w) {
  const double len = glm::length(w), limit = opt_.max_angular_rate_dps * kDegToRad;
  if (len <= limit) return w;
  ++counters_.clamped_rates;
  return w * (limit / len);
}

// The sample to difference the newest against: the newest one at least
// 0.9 packet intervals older (two samples squeezed together by the network
// or the sender clock's minimum step would overstate the rate), else the
// one before the newest.
const PoseFilter::Entry& PoseFilter::derive_base() const {
  const double newest = at(count_ - 1).t;
  for (int k = count_ - 2; k >= 0; --k)
    if (newest - at(k).t >= 0.9 * interval_) return at(k);
  return at(count_ - 2);
}

// Differencing: the step is floored at a fraction of the packet interval (two
// poses stamped microseconds apart must not make a huge velocity) and the
// result clamped to physical limits.
glm::dvec3 PoseFilter::extrap_velocity() {
  const Entry& n = at(count_ - 1);
  if (n.has_vel) return n.vel;
  if (!opt_.derive_missing_rates || count_ < 2) return glm::dvec3(0.0);
  const Entry& p = derive_base();
  const double h = n.t - p.t;
  if (!(h > 0.0) || h > kMaxDiffGapS) return glm::dvec3(0.0);
  return clamp_velocity((n.pos - p.pos) / std::max(h, opt_.min_derive_step_fraction * interval_));
}

glm::dvec3 PoseFilter::extrap_omega() {
  const Entry& n = at(count_ - 1);
  if (n.has_omega) return n.omega;
  if (!opt_.derive_missing_rates || count_ < 2) return glm::dvec3(0.0);
  const Entry& p = derive_base();
  const double h = n.t - p.t;
  if (!(h > 0.0) || h > kMaxDiffGapS) return glm::dvec3(0.0);
  return clamp_omega(quat::log_rotvec(glm::conjugate(p.att) * n.att) /
                     std::max(h, opt_.min_derive_step_fraction * interval_));  // body frame
}

FilteredPose PoseFilter::interpolate(const Entry& a, const Entry& b, double tau) const {
  FilteredPose out;
  const double h = b.t - a.t;
  const double s = std::clamp((tau - a.t) / h, 0.0, 1.0);
  if (a.has_vel && b.has_vel) {
    const double s2 = s * s, s3 = s2 * s;
    out.position = a.pos * (2 * s3 - 3 * s2 + 1) + a.vel * (h * (s3 - 2 * s2 + s)) +
                   b.pos * (-2 * s3 + 3 * s2) + b.vel * (h * (s3 - s2));
  } else {
    out.position = a.pos + (b.pos - a.pos) * s;
  }
  if (a.has_omega && b.has_omega) {
    // The relative rotation is ambiguous by whole turns (and q ~ -q): pick
    // the branch closest to what the body rates integrate to over the gap.
    glm::dvec3 rel = quat::log_rotvec(glm::conjugate(a.att) * b.att);  // |rel| <= pi
    const glm::dvec3 want = (a.omega + b.omega) * (0.5 * h);
    const double len = glm::length(rel);
    glm::dvec3 axis = len > 1e-9 ? rel / len : glm::dvec3(0.0);
    if (len <= 1e-9) {
      const double wl = glm::length(want);
      if (wl > 1e-9) axis = want / wl;
    }
    glm::dvec3 best = rel;
    double best_d = glm::length(want - rel);
    for (int k = -3; k <= 3; ++k) {
      if (k == 0) continue;
      const glm::dvec3 cand = rel + axis * (2.0 * kPi * k);
      const double d = glm::length(want - cand);
      if (d < best_d) {
        best_d = d;
        best = cand;
      }
    }
    out.attitude = glm::normalize(a.att * quat::exp_rotvec(best * s));
  } else {
    out.attitude = quat::slerp_short(a.att, b.att, s);
  }
  out.mode = FilteredPose::Interpolating;
  return out;
}

std::optional<FilteredPose> PoseFilter::sample(double now_s, double display_lead_s) {
  if (count_ == 0) return std::nullopt;
  if (!std::isfinite(now_s)) now_s = clock_init_ ? last_now_ : at(count_ - 1).recv;

  if (count_ == 1 && !clock_init_ && opt_.latency == LatencyMode::Smooth) {
    // One sample of a new stream: nothing to interpolate towards and no
    // packet interval yet. Show it and start the timeline when the second
    // arrives (started now, the timeline would run ahead of a slow stream
    // with a nominal delay and jump when the second sample came).
    FilteredPose out;
    out.position = at(0).pos;
    out.attitude = at(0).att;
    out.mode = FilteredPose::Holding;
    out.age_s = now_s - at(0).recv;
    out.sample_time_s = at(0).t;
    out.render_time_s = at(0).t + offset_;
    out.playout_delay_s = playout_delay_s();
    ++counters_.holds;
    last_out_ = out;
    have_output_ = true;
    return out;
  }
  // Playout point: now - (offset + delay), the sum slewed for a smooth timeline.
  const double delay = playout_delay_s();
  const double target = offset_ + delay;
  if (!clock_init_) {
    budget_ = target;
    // Coming from the held first sample (the only output a stream gives
    // before its timeline starts): start the timeline there and let the slew
    // bring it to the target delay (10 % fast for a moment) rather than jump
    // ahead by up to an interval.
    if (have_output_) budget_ = std::clamp(now_s - at(0).t, target, target + opt_.clock_snap_s);
    clock_init_ = true;
  } else {
    const double dt = now_s - last_now_;
    if (dt > 0.0 && dt < 1.0) {
      const double step = opt_.clock_slew * dt;
      budget_ += std::clamp(target - budget_, -step, step);
    }
    if (std::fabs(target - budget_) > opt_.clock_snap_s) budget_ = target;
  }
  last_now_ = now_s;
  // The rendered timeline never runs backwards: when the playout point would
  // move back (the IG clock stepped back, or the offset estimate rose by more
  // than clock_snap_s), hold the last instant until it catches up.
  const Entry& newest_entry = at(count_ - 1);
  if (!std::isfinite(display_lead_s) || display_lead_s < 0.0) display_lead_s = 0.0;
  double want = now_s - budget_;  // Smooth: a playout delay behind
  if (opt_.latency == LatencyMode::Latest) {
    // The sender's instant when this frame reaches the screen: the receive
    // clock maps to the sender's through the (min-filtered) offset.
    // Never further than the newest pose's age plus the lead (and the
    // jitter): a stamp the offset estimate places too early (a clock still
    // locking) must not throw the pose ahead.
    const double ahead = std::min(now_s + display_lead_s - offset_ - newest_entry.t,
                                  now_s + display_lead_s - newest_entry.recv + jitter_);
    want = newest_entry.t + std::max(0.0, ahead);
  } else if (opt_.latency == LatencyMode::Synchronous) {
    want = newest_entry.t;  // exactly the newest pose the host sent
  }
  const double tau = std::max(want, last_tau_);

  FilteredPose out;
  const Entry& oldest = at(0);
  const Entry& newest = at(count_ - 1);
  if (tau <= oldest.t) {
    // Before the first buffered sample (start-up, or after a reset).
    out.position = oldest.pos;
    out.attitude = oldest.att;
    out.mode = FilteredPose::Holding;
    out.age_s = now_s - oldest.recv;
  } else if (tau <= newest.t) {
    int k = count_ - 1;
    while (k > 0 && at(k - 1).t >= tau) --k;  // at(k-1).t < tau <= at(k).t
    out = interpolate(at(k - 1), at(k), tau);
    out.age_s = now_s - at(k).recv;
  } else {
    const double dt = tau - newest.t;
    const double de = std::min(dt, opt_.max_extrapolation_s);
    glm::dvec3 step = extrap_velocity() * de;
    const double dist = glm::length(step);
    if (dist > opt_.max_extrapolation_m) {
      step *= opt_.max_extrapolation_m / dist;
      ++counters_.clamped_extrapolations;
    }
    out.position = newest.pos + step;
    out.attitude = glm::normalize(newest.att * quat::exp_rotvec(extrap_omega() * de));
    out.mode = dt <= opt_.max_extrapolation_s ? FilteredPose::Extrapolating : FilteredPose::Holding;
    out.age_s = now_s - newest.recv;
  }
  out.sample_time_s = tau;
  out.render_time_s = tau + offset_;
  out.playout_delay_s = delay;

  if (!quat::finite(out.position) || !quat::finite(out.attitude) || !std::isfinite(out.age_s) ||
      !std::isfinite(out.sample_time_s)) {
    // Cannot happen with finite inputs; never hand NaN to the renderer.
    if (have_output_) {
      out = last_out_;
    } else {
      out.position = newest.pos;
      out.attitude = newest.att;
      out.age_s = 0.0;
      out.sample_time_s = newest.t;
      out.render_time_s = newest.recv;
    }
    out.mode = FilteredPose::Holding;
  }
  if (out.mode == FilteredPose::Extrapolating) ++counters_.extrapolations;
  if (out.mode == FilteredPose::Holding) ++counters_.holds;
  last_tau_ = std::max(last_tau_, tau);
  last_out_ = out;
  have_output_ = true;
  return out;
}

}  // namespace ig::io
