// The pose filter's output side (PoseFilter::sample, docs/pose-filter.md):
// interpolation between buffered poses and bounded extrapolation past the
// newest, with rates differenced or sent and clamped to physical limits.
#include "io/filter/pose_filter.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "io/filter/pose_filter_constants.h"
#include "io/filter/quat_util.h"

namespace ig::io {

using namespace pose_filter_detail;

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

// Differencing: the sample to difference the newest against and the step
// between them, floored at a fraction of the packet interval (two poses
// stamped microseconds apart must not make a huge velocity); nullptr when
// rates are not derived or the two are too far apart. The rates are clamped
// to physical limits.
const PoseFilter::Entry* PoseFilter::derive_from(double& step) const {
  if (!opt_.derive_missing_rates || count_ < 2) return nullptr;
  const Entry& p = derive_base();
  const double h = at(count_ - 1).t - p.t;
  if (!(h > 0.0) || h > kMaxDiffGapS) return nullptr;
  step = std::max(h, opt_.min_derive_step_fraction * interval_);
  return &p;
}

glm::dvec3 PoseFilter::extrap_velocity() {
  const Entry& n = at(count_ - 1);
  if (n.has_vel) return n.vel;
  double step = 0.0;
  const Entry* p = derive_from(step);
  return p ? clamp_velocity((n.pos - p->pos) / step) : glm::dvec3(0.0);
}

glm::dvec3 PoseFilter::extrap_omega() {
  const Entry& n = at(count_ - 1);
  if (n.has_omega) return n.omega;
  double step = 0.0;
  const Entry* p = derive_from(step);
  return p ? clamp_omega(quat::log_rotvec(glm::conjugate(p->att) * n.att) / step) : glm::dvec3(0.0);  // body frame
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
