#include "io/filter/sender_clock.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ig::io {
namespace {
constexpr double kMinPeriodS = 1e-3;  // 1 kHz: faster senders are clamped to this period
constexpr double kMaxPeriodS = 5.0;
constexpr double kCountedStepFraction = 0.8;  // the fastest playout: 1 / 0.8 = 1.25 x the flown speed
constexpr std::int32_t kMaxSequenceStep = 1000;  // further: a counter restart or a different sender
}  // namespace

SenderClock::SenderClock(const SenderClockOptions& options) : opt_(options) {
  if (!(opt_.nominal_interval_s >= kMinPeriodS && opt_.nominal_interval_s <= kMaxPeriodS))
    opt_.nominal_interval_s = 1.0 / 60.0;
  if (!(opt_.window_s > 0.0)) opt_.window_s = 2.0;
  opt_.min_step_fraction = std::clamp(std::isfinite(opt_.min_step_fraction) ? opt_.min_step_fraction : 0.5, 0.0, 1.0);
  if (!(opt_.relock_gap_s > 0.0)) opt_.relock_gap_s = 0.5;
  if (!(opt_.relock_gap_periods > 1.0)) opt_.relock_gap_periods = 8.0;
  opt_.relock_late_count = std::max(2, opt_.relock_late_count);
  if (!(opt_.relock_lateness_periods > 0.0)) opt_.relock_lateness_periods = 2.0;
  reset();
}

void SenderClock::reset() {
  clear_window();
  gap_count_ = gap_next_ = 0;
  started_ = false;
  period_ = opt_.nominal_interval_s;
  last_seq_.reset();
  late_run_ = 0;
  last_lateness_ = 0.0;
}

double SenderClock::rounding_period() const {
  if (gap_count_ == 0) return period_;
  // Lower median: one-sided jitter makes a late packet's gap long and the
  // next one short; back-to-back pairs make a few gaps near zero.
  std::array<double, kGaps> g{};
  std::copy_n(gaps_.begin(), gap_count_, g.begin());
  const auto mid = g.begin() + (gap_count_ - 1) / 2;
  std::nth_element(g.begin(), mid, g.begin() + gap_count_);
  return std::clamp(*mid, kMinPeriodS, kMaxPeriodS);
}

double SenderClock::envelope(std::int64_t index, double arrival_s) const {
  double e = arrival_s;
  for (int k = 0; k < count_; ++k) e = std::min(e, at(k).arrival + period_ * double(index - at(k).index));
  return e;
}

void SenderClock::fit_period() {
  if (count_ < kMinFit) {
    // Too few points for the fit yet: the gaps' median, unless the counter
    // already counts in the period held.
    if (unit_ == CounterUnit::SenderPackets) period_ = rounding_period();
    return;
  }
  // The envelope point (least delayed packet) of the older and of the newer
  // half of the window; the period is the slope between them.
  auto envelope_point = [&](int from, int to) {
    int best = from;
    for (int k = from + 1; k < to; ++k)
      if (at(k).arrival - period_ * double(at(k).index) < at(best).arrival - period_ * double(at(best).index)) best = k;
    return at(best);
  };
  const Point a = envelope_point(0, count_ / 2);
  const Point b = envelope_point(count_ / 2, count_);
  if (b.index <= a.index) return;
  const double p = (b.arrival - a.arrival) / double(b.index - a.index);
  // Smoothed: each fit moves the period a fifth of the way (the envelope
  // points change as the window slides; the period should not jump with them).
  if (p >= kMinPeriodS && p <= kMaxPeriodS) period_ += 0.2 * (p - period_);
}

void SenderClock::add(double arrival_s, std::int64_t index) {
  if (count_ == kWindow) {
    head_ = (head_ + 1) % kWindow;
    --count_;
  }
  win_[(head_ + count_) % kWindow] = {arrival_s, index};
  ++count_;
  while (count_ > 2 && at(0).arrival < arrival_s - opt_.window_s) {
    head_ = (head_ + 1) % kWindow;
    --count_;
  }
  fit_period();
}

double SenderClock::relock(double arrival_s, std::optional<std::uint32_t> sequence) {
  const bool was_started = started_;
  clear_window();
  late_run_ = 0;
  last_lateness_ = 0.0;
  // Continue strictly after the last stamp (a counter restart without a gap
  // must not step back); after a silence the arrival is later anyway.
  const double s = was_started ? std::max(arrival_s, last_stamp_ + opt_.min_step_fraction * period_) : arrival_s;
  if (was_started) ++counters_.relocks;
  started_ = true;
  last_index_ = 0;
  last_seq_ = sequence;
  last_arrival_ = arrival_s;
  last_stamp_ = s;
  add(arrival_s, 0);
  ++counters_.stamped;
  return s;
}

double SenderClock::stamp(double arrival_s, std::optional<std::uint32_t> sequence, CounterUnit unit) {
  if (!std::isfinite(arrival_s)) return started_ ? last_stamp_ : 0.0;
  unit_ = sequence ? unit : CounterUnit::SenderPackets;
  if (!started_) return relock(arrival_s, sequence);
  // Receive times never run back on one socket; clamp rather than trust a
  // recording edited by hand.
  arrival_s = std::max(arrival_s, last_arrival_);
  const double gap = arrival_s - last_arrival_;
  if (gap > std::max(opt_.relock_gap_s, opt_.relock_gap_periods * period_)) return relock(arrival_s, sequence);
  if (sequence.has_value() != last_seq_.has_value()) return relock(arrival_s, sequence);

  std::int64_t step = 0;
  if (sequence) {
    const std::int32_t d = static_cast<std::int32_t>(*sequence - *last_seq_);  // wrap-safe
    if (d > kMaxSequenceStep || d < -kMaxSequenceStep) return relock(arrival_s, sequence);
    if (d <= 0) return envelope(last_index_ + d, std::numeric_limits<double>::infinity());  // stale
    step = d;
  } else {
    const double rp = rounding_period();
    if (gap_count_ > 0 && std::fabs(rp - period_) > 0.25 * period_) {
      // The indices so far were counted with a wrong period (the nominal
      // one at start-up, or the sender changed rate): start the window again.
      clear_window();
      period_ = rp;
    }
    step = std::max<std::int64_t>(1, std::llround((arrival_s - last_stamp_) / rp));
  }

  // Arrival gap for the rounding period (robust median): per index step when
  // the sequence says how many, else the raw gap (the rounding's own input).
  gaps_[gap_next_] = sequence ? gap / double(step) : gap;
  gap_next_ = (gap_next_ + 1) % kGaps;
  gap_count_ = std::min(gap_count_ + 1, kGaps);

  if (!locked() && unit_ == CounterUnit::SenderPackets) period_ = rounding_period();  // see fit_period()

  const std::int64_t index = last_index_ + step;
  // Where the window's envelope puts this index.
  double slot = envelope(index, std::numeric_limits<double>::infinity());
  if (locked() && arrival_s < slot - 0.25 * period_) {
    // Before its slot by more than a quarter period: a periodic sender's
    // packets cannot do that (delay only adds), so the sender's phase moved
    // (FlightGear after a stalled frame). Fit a new window from here.
    clear_window();
    slot = std::numeric_limits<double>::infinity();
    ++counters_.rephases;
  }
  // The envelope drops at once for an early arrival; once locked it rises at
  // most 1 % of a period per index (when its lowest point leaves the
  // window), so the stamps stay regular.
  double env = std::min(slot, arrival_s);
  if (locked()) env = std::min(env, last_stamp_ + 1.01 * period_ * double(step));
  // A counter in this clock's periods measures sender time: its stamps may
  // close up less (an early first packet must not play out a bunched pair fast).
  const double fraction =
      unit_ == CounterUnit::ClockPeriods ? std::max(opt_.min_step_fraction, kCountedStepFraction) : opt_.min_step_fraction;
  const double floor = last_stamp_ + fraction * period_ * double(step);
  double s = env;
  if (s < floor) {
    s = floor;
    ++counters_.spread;
  }
  if (s < arrival_s - 1e-3) ++counters_.pulled_earlier;

  // A sender that slowed down arrives later and later behind the envelope
  // projected with the old period: after a run of such packets, re-lock.
  const double lateness = arrival_s - s;
  if (lateness > opt_.relock_lateness_periods * period_ && lateness > last_lateness_) ++late_run_;
  else late_run_ = 0;
  last_lateness_ = lateness;
  if (late_run_ >= opt_.relock_late_count) return relock(arrival_s, sequence);

  add(arrival_s, index);
  last_index_ = index;
  last_seq_ = sequence;
  last_arrival_ = arrival_s;
  last_stamp_ = s;
  ++counters_.stamped;
  return s;
}

}  // namespace ig::io
