#pragma once
// De-jittered sender time base for pose streams that carry no usable sender
// clock (FlightGear FGNetFDM; CIGI with the timestamp-valid bit clear; any
// host whose clock is absent). From the arrival times alone (and the packet
// counter when there is one) it estimates the sender's period and phase and
// stamps each packet with the instant the sender most plausibly sent it, so
// that arrival jitter, and two datagrams that arrive back to back, do not
// become motion.
//
// Model: the sender sends packet n near phase + n * period; the network only
// ever adds delay. So the ideal send times form the lower envelope of the
// arrivals: stamp(n) = min over recent packets j of (arrival_j + period *
// (n - n_j)) -- the earliest arrival in the window projected forward. A packet
// that arrives early pulls the envelope down at once; a late one is placed
// where the envelope says. The period is the slope between the envelope
// points of the older and newer half of the window (a robust fit that
// ignores one-sided jitter). Packet indices n come from the sequence number
// when the stream has one, else from rounding the arrival gap to whole
// periods (at least one). Long gaps and rate changes re-lock the estimate.
// Full description and limits: docs/pose-filter.md.
//
// Everything is in seconds on the receiver's clock. Fixed storage, no
// allocation, not thread-safe.

#include <array>
#include <cstdint>
#include <optional>

namespace ig::io {

struct SenderClockOptions {
  double nominal_interval_s = 1.0 / 60.0;  // until the stream shows its own
  double window_s = 2.0;                   // envelope / fit window (arrival time)
  // A stamp never advances less than this fraction of a period per packet
  // index (back-to-back arrivals are spread to at least this).
  double min_step_fraction = 0.5;
  // Re-lock (start a fresh estimate) after a silence longer than
  // max(relock_gap_s, relock_gap_periods * period) ...
  double relock_gap_s = 0.5;
  double relock_gap_periods = 8.0;
  // ... or when this many packets in a row arrive later than the envelope by
  // more than relock_lateness_periods periods and growing (the sender slowed).
  int relock_late_count = 6;
  double relock_lateness_periods = 2.0;
};

// What a stream's counter counts: the sender's packets (a real sequence
// number), or periods of this clock's own estimate (a counter made by the
// receiver, io/filter/motion_counter.h: index x period is already sender
// time, so before the clock locks the period must stay the one it was
// counted in; bunched arrival gaps would shrink it and speed the playout).
enum class CounterUnit { SenderPackets, ClockPeriods };

struct SenderClockCounters {
  std::uint64_t stamped = 0;
  std::uint64_t relocks = 0;         // gaps, rate changes, counter restarts
  std::uint64_t rephases = 0;        // a packet early by > period / 4: the sender's phase moved
  std::uint64_t pulled_earlier = 0;  // stamp below the arrival by more than 1 ms (late packets)
  std::uint64_t spread = 0;          // stamp raised by the minimum step (back-to-back arrivals)
};

class SenderClock {
 public:
  explicit SenderClock(const SenderClockOptions& options = {});

  // The sender time for a packet that arrived at arrival_s (receiver clock),
  // with the sender's packet counter when the stream has one. Stamps of
  // in-order packets strictly increase. A stale packet (counter at or behind
  // the newest) gets the envelope time of its index without changing state.
  double stamp(double arrival_s, std::optional<std::uint32_t> sequence = std::nullopt,
               CounterUnit unit = CounterUnit::SenderPackets);

  void reset();
  double period_s() const { return period_; }
  bool locked() const { return count_ >= kMinFit; }  // period fitted from the window
  const SenderClockCounters& counters() const { return counters_; }

  static constexpr int kWindow = 64;
  static constexpr int kMinFit = 8;
  static constexpr int kGaps = 31;  // per-index arrival gaps kept for the rounding median

 private:
  struct Point {
    double arrival = 0.0;
    std::int64_t index = 0;
  };
  const Point& at(int k) const { return win_[(head_ + k) % kWindow]; }
  void clear_window() { head_ = count_ = 0; }
  double relock(double arrival_s, std::optional<std::uint32_t> sequence);
  void add(double arrival_s, std::int64_t index);
  void fit_period();
  double envelope(std::int64_t index, double arrival_s) const;
  double rounding_period() const;

  SenderClockOptions opt_;
  SenderClockCounters counters_;
  std::array<Point, kWindow> win_{};
  int head_ = 0, count_ = 0;
  std::array<double, kGaps> gaps_{};
  int gap_count_ = 0, gap_next_ = 0;
  bool started_ = false;
  double period_ = 1.0 / 60.0;
  CounterUnit unit_ = CounterUnit::SenderPackets;  // of the packet being stamped
  double last_arrival_ = 0.0, last_stamp_ = 0.0;
  std::int64_t last_index_ = 0;
  std::optional<std::uint32_t> last_seq_;
  int late_run_ = 0;
  double last_lateness_ = 0.0;
};

}  // namespace ig::io
