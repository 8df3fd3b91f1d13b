#pragma once
// Pose intake filter: turns a jittery, lossy, possibly reordered stream of
// host pose packets into one smooth pose per rendered frame.
//
//  * drops duplicates, stale (out-of-order) and non-finite packets, counting
//    each; late packets that are still ahead of the playout point are
//    inserted instead of dropped (PoseFilterOptions::insert_late_packets);
//  * maps the sender's clock onto the IG clock with a min-filtered offset and
//    plays the stream out a small, adaptive delay behind the newest data
//    (jitter buffer), interpolating between the two samples around the
//    playout instant: position by cubic Hermite when both carry velocities,
//    else linearly; attitude by slerp (short arc, or the arc the body rates
//    say when both carry rates, so 720 deg/s rolls survive packet loss);
//  * extrapolates from the newest sample with its velocity and body rates for
//    at most max_extrapolation_s when data runs dry, then holds that pose;
//  * resets on sender clock jumps;
//  * never outputs NaN/Inf.
// Frames and units: see PoseSample. Full description: docs/pose-filter.md.
// Not thread-safe: push() and sample() from the same thread (or lock).

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "io/filter/motion_counter.h"
#include "io/filter/sender_clock.h"

namespace ig::io {

// How the filter trades latency for smoothness (docs/pose-filter.md):
//  Smooth      interpolate a playout delay behind the newest data; the delay
//              adapts to the measured packet interval and jitter;
//  Latest      the newest pose extrapolated to the frame's expected display
//              time: minimum latency, arrival jitter shows as small errors;
//  Synchronous the newest pose as received, no extrapolation (CIGI
//              synchronous operation: one IG frame per host frame).
enum class LatencyMode : std::uint8_t { Smooth = 0, Latest = 1, Synchronous = 2 };
const char* latency_mode_name(LatencyMode m);  // "smooth", "latest", "sync"
std::optional<LatencyMode> parse_latency_mode(const std::string& text);  // the names above

struct PoseSample {
  // IG clock (the clock sample() is called with), seconds, when the packet
  // was received. Must be taken per datagram (kernel timestamp), never once
  // per frame poll.
  double receive_time_s = 0.0;
  // Sender's clock, seconds, when the pose was valid. Strongly recommended:
  // without it the filter stamps packets with a de-jittered estimate of the
  // sender's send times (io/filter/sender_clock.h), which removes arrival
  // jitter for periodic senders but cannot see the host's own irregularity.
  std::optional<double> sender_time_s;
  // Packet counter, incremented by one per packet sent; wraps at 2^32.
  std::optional<std::uint32_t> sequence;
  // Terrain-local ENU metres (x east, y north, z up); convert geodetic first
  // (io/filter/geodesy.h).
  glm::dvec3 position{0.0};
  // Body -> world rotation in the io/pose.h convention (body x right, y
  // forward, z up; attitude_from_hpr). Need not be normalised; zero -> dropped.
  glm::dquat attitude{1.0, 0.0, 0.0, 0.0};
  // World (ENU) velocity, metres per second.
  std::optional<glm::dvec3> velocity_mps;
  // Body angular rates, degrees per second, aerospace convention:
  //   [0] roll rate p:  about body +y (forward), right-handed: right wing down +
  //   [1] pitch rate q: about body +x (right), right-handed: nose up +
  //   [2] yaw rate r:   nose right +, i.e. LEFT-handed about body +z (up), the
  //                     sense in which heading increases.
  // So the body-frame angular velocity vector (x, y, z) is (q, p, -r).
  // These are body rates (angular velocity), not Euler-angle rates.
  std::optional<glm::dvec3> body_rates_dps;
  std::string source;  // for logs; not used by the filter
};

struct FilteredPose {
  glm::dvec3 position{0.0};
  glm::dquat attitude{1.0, 0.0, 0.0, 0.0};  // unit
  double age_s = 0.0;  // now - receive time of the newest sample used
  enum Mode { Interpolating, Extrapolating, Holding } mode = Holding;
  // The instant the pose represents, in the stream's time base (sender clock
  // when the stream carries sender times, else the IG receive clock) ...
  double sample_time_s = 0.0;
  // ... and that instant on the IG clock (sample_time_s + clock offset).
  double render_time_s = 0.0;
  double playout_delay_s = 0.0;  // the delay in effect for this output
};

struct PoseFilterCounters {
  std::uint64_t received = 0;        // push() calls
  std::uint64_t accepted = 0;        // samples that entered the buffer (incl. late_inserted)
  std::uint64_t duplicates = 0;      // same sequence (or sender time) seen before: dropped
  std::uint64_t out_of_order = 0;    // older than the newest accepted, not a duplicate
  std::uint64_t late_inserted = 0;   // ... of which still ahead of playout: inserted, used
  std::uint64_t non_finite = 0;      // NaN/Inf anywhere, or a zero quaternion: dropped
  std::uint64_t time_jumps = 0;      // sender clock jumps (and time-base changes): reset
  std::uint64_t sequence_resets = 0;  // sequence restarted (jumped back > reorder_window)
  std::uint64_t extrapolations = 0;  // sample() outputs in mode Extrapolating
  std::uint64_t holds = 0;           // sample() outputs in mode Holding
  std::uint64_t clamped_rates = 0;   // derived velocity / rate above the physical limits: clamped
  std::uint64_t clamped_extrapolations = 0;  // extrapolation cut at max_extrapolation_m
};

struct PoseFilterOptions {
  LatencyMode latency = LatencyMode::Smooth;
  // Playout delay: >= 0 fixes it (seconds); negative (default) adapts it to
  //   playout_intervals * packet interval + min(jitter_factor * jitter, max_playout_delay_s),
  // at least min_playout_delay_s (the interval part alone may exceed max_playout_delay_s:
  // a slow host is interpolated, not extrapolated). The packet
  // interval is estimated from sender time deltas per sequence step; jitter
  // is the spread (max - min) of receive-minus-sender time over
  // offset_window_s.
  // One interval plus the jitter is what interpolation needs: the next
  // packet is at most one interval plus its extra delay away.
  double playout_delay_s = -1.0;
  double playout_intervals = 1.0;
  double jitter_factor = 1.0;
  double min_playout_delay_s = 0.0;
  double max_playout_delay_s = 0.100;
  double nominal_interval_s = 1.0 / 60.0;  // until two packets have been seen
  // Sender -> IG clock offset: the minimum of (receive - sender time) over
  // this much recent sender time (robust to one-sided network jitter).
  double offset_window_s = 2.0;
  // The playout point (now - offset - delay) follows changes of offset and
  // delay at most this fast (seconds per second, so the rendered timeline
  // runs at 1 +- clock_slew), unless they differ by more than clock_snap_s.
  double clock_slew = 0.1;
  double clock_snap_s = 0.25;
  // Extrapolate at most this far past the newest sample (in time and in
  // distance), then hold.
  double max_extrapolation_s = 0.2;
  double max_extrapolation_m = 100.0;
  // Velocity and rates differenced from successive poses (packets without
  // them) use a time step of at least min_derive_step_fraction packet
  // intervals and are clamped to these physical limits.
  double min_derive_step_fraction = 0.5;
  double max_speed_mps = 1000.0;
  double max_angular_rate_dps = 1000.0;
  // Streams without sender times: stamp them with the de-jittered sender
  // clock (false: the raw receive times, as before).
  bool dejitter_receive_times = true;
  SenderClockOptions sender_clock;
  // A sender time off by more than this from the expected progression
  // (last sender time + receive time elapsed since) resets the filter.
  double time_jump_s = 1.0;
  // Smaller clock steps (either clock, either way) show as a change of the
  // receive-minus-sender offset that network delay cannot explain: a packet
  // more than this below the window's minimum (delay never drops below its
  // floor), or every packet more than this above it for this long (sender
  // time). Either resets the filter too.
  double clock_step_s = 0.25;
  // Sequence numbers less than this far behind the newest are stale packets;
  // further behind, the sender restarted its counter.
  std::uint32_t reorder_window = 1000;
  // Insert late (out-of-order) packets that are still ahead of the playout
  // point instead of dropping them. false: drop every out-of-order packet.
  bool insert_late_packets = true;
  // Without velocity / body rates in the packets, extrapolate with rates
  // differenced from the two newest samples (false: hold position/attitude).
  bool derive_missing_rates = true;
};

class PoseFilter {
 public:
  explicit PoseFilter(const PoseFilterOptions& options = {});

  // Feed one received packet. true when it entered the buffer.
  bool push(const PoseSample& s);
  // The pose to render at IG time now_s. nullopt until the first valid
  // sample. Call once per frame with a non-decreasing clock. display_lead_s:
  // how long after now_s the frame is expected on screen (Latest mode
  // extrapolates to now_s + display_lead_s; the others ignore it).
  std::optional<FilteredPose> sample(double now_s, double display_lead_s = 0.0);

  // Forget all samples and clock estimates (counters kept).
  void reset();
  void set_latency_mode(LatencyMode m) { opt_.latency = m; }
  LatencyMode latency_mode() const { return opt_.latency; }
  const SenderClock& sender_clock() const { return sender_clock_; }

  const PoseFilterCounters& counters() const { return counters_; }
  const PoseFilterOptions& options() const { return opt_; }
  double playout_delay_s() const;      // target delay now
  double clock_offset_s() const { return offset_; }   // receive - sender, min-filtered
  double jitter_s() const { return jitter_; }
  double packet_interval_s() const { return interval_; }
  int buffered() const { return count_; }

  static constexpr int kCapacity = 128;     // samples kept (about 2 s at 60 Hz)
  static constexpr int kOffsetWindow = 256;  // receive-sender samples kept
  static constexpr int kSeenRing = 256;      // recent ids for duplicate detection

 private:
  struct Entry {
    double t = 0.0;     // stream time (sender, else receive)
    double recv = 0.0;  // IG receive time
    std::uint32_t seq = 0;
    glm::dvec3 pos{0.0};
    glm::dquat att{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 vel{0.0};
    glm::dvec3 omega{0.0};  // body-frame angular velocity, rad/s (x, y, z)
    bool has_vel = false;
    bool has_omega = false;
  };

  void clear_stream();
  glm::dvec3 clamp_velocity(glm::dvec3 v);
  glm::dvec3 clamp_omega(glm::dvec3 w);
  Entry& at(int k) { return buf_[(head_ + k) % kCapacity]; }
  const Entry& at(int k) const { return buf_[(head_ + k) % kCapacity]; }
  void restart(const Entry& e);
  void append(const Entry& e);
  bool insert_sorted(const Entry& e);
  void note_offset(double t, double recv);
  void note_seen(std::uint32_t seq, double t);
  bool seen(std::uint32_t seq, double t) const;
  const Entry& derive_base() const;
  const Entry* derive_from(double& step) const;
  glm::dvec3 extrap_velocity();
  glm::dvec3 extrap_omega();
  FilteredPose interpolate(const Entry& a, const Entry& b, double tau) const;

  PoseFilterOptions opt_;
  PoseFilterCounters counters_;
  SenderClock sender_clock_;
  MotionCounter motion_;  // the packet counter of a stream with velocities but no counter or sender time
  std::optional<std::uint32_t> clock_sequence(const PoseSample& s);
  static CounterUnit clock_counter_unit(const PoseSample& s);  // what clock_sequence counts

  std::array<Entry, kCapacity> buf_{};
  int head_ = 0, count_ = 0;
  bool stream_has_sender_ = false, stream_has_seq_ = false;
  std::uint32_t newest_seq_ = 0;  // sequence of the newest in-order sample

  std::array<double, kOffsetWindow> off_t_{}, off_v_{};
  int off_next_ = 0, off_count_ = 0;
  double offset_ = 0.0, jitter_ = 0.0;

  std::array<std::uint32_t, kSeenRing> seen_seq_{};
  std::array<double, kSeenRing> seen_t_{};
  int seen_next_ = 0, seen_count_ = 0;

  double interval_ = 1.0 / 60.0;
  bool interval_known_ = false;

  bool clock_init_ = false;
  bool above_ = false;       // packets have run above offset + clock_step_s ...
  double above_since_ = 0.0;  // ... since this sender time
  double budget_ = 0.0;  // offset + delay in effect (slewed)
  double last_now_ = 0.0;
  double last_tau_ = 0.0;  // stream time of the last output
  bool have_output_ = false;
  FilteredPose last_out_{};
};

}  // namespace ig::io
