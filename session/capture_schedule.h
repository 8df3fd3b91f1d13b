#pragma once
// Which frames save PNGs: the scenario's capture.times_s and, with
// capture.every_s, every multiple of it from 0. One rule for ig run (frame k
// at sim time k * step) and ig serve (frames at seconds since it started):
// a scheduled time is served by the first frame whose time reaches it less
// `tolerance_s`. ig run passes just under half a step, which makes that the
// frame nearest to it (round(t / step), ties to the later frame); ig serve
// passes 0, the first frame at or after it.

#include <cstddef>
#include <vector>

#include "io/scenario.h"

namespace ig::session {

class CaptureSchedule {
 public:
  // times_s in any order (repeats are one capture); every_s 0 = none.
  CaptureSchedule(std::vector<double> times_s, double every_s, double tolerance_s);
  CaptureSchedule(const io::Scenario& s, double tolerance_s)
      : CaptureSchedule(s.capture_times_s, s.capture_every_s, tolerance_s) {}

  // ig run's tolerance for a fixed step: the nearest frame serves each time.
  static double nearest_frame_tolerance(double step_s) { return 0.5 * step_s * (1.0 - 1e-6); }

  // Whether the frame at t_s saves PNGs: it serves every scheduled time up
  // to t_s + tolerance that no earlier frame served. Frame times increase.
  bool take(double t_s);
  // The first `limit` scheduled times up to until_s that no frame has
  // served yet, in order; pending_count: how many there are in all.
  std::vector<double> pending(double until_s, std::size_t limit) const;
  std::size_t pending_count(double until_s) const;

 private:
  std::vector<double> times_;  // sorted, unique
  std::size_t next_time_ = 0;
  double every_s_ = 0.0;
  long long next_multiple_ = 0;  // every_s_ * next_multiple_ is the next periodic time
  double tolerance_s_ = 0.0;
};

}  // namespace ig::session
