#include "session/capture_schedule.h"

#include <algorithm>
#include <cmath>

namespace ig::session {

CaptureSchedule::CaptureSchedule(std::vector<double> times_s, double every_s, double tolerance_s)
    : times_(std::move(times_s)), every_s_(every_s > 0.0 && std::isfinite(every_s) ? every_s : 0.0),
      tolerance_s_(tolerance_s) {
  std::sort(times_.begin(), times_.end());
  times_.erase(std::unique(times_.begin(), times_.end()), times_.end());
}

bool CaptureSchedule::take(double t_s) {
  const double reach = t_s + tolerance_s_;
  bool due = false;
  for (; next_time_ < times_.size() && times_[next_time_] <= reach; ++next_time_) due = true;
  if (every_s_ > 0.0 && reach >= 0.0) {
    // The first multiple past `reach`, computed rather than stepped to (a
    // live IG may pause for many periods), then nudged past rounding.
    auto m = static_cast<long long>(std::floor(reach / every_s_)) + 1;
    while (m > 0 && (m - 1) * every_s_ > reach) --m;
    while (m * every_s_ <= reach) ++m;
    if (m > next_multiple_) {
      next_multiple_ = m;
      due = true;
    }
  }
  return due;
}

std::vector<double> CaptureSchedule::pending(double until_s, std::size_t limit) const {
  std::vector<double> out;
  std::size_t k = next_time_;
  long long m = next_multiple_;
  while (out.size() < limit) {  // the two sorted lists merged
    const double listed = k < times_.size() ? times_[k] : INFINITY;
    const double periodic = every_s_ > 0.0 ? m * every_s_ : INFINITY;
    const double t = std::min(listed, periodic);
    if (!(t <= until_s)) break;
    out.push_back(t);
    if (listed == t) ++k;
    if (periodic == t) ++m;
  }
  return out;
}

std::size_t CaptureSchedule::pending_count(double until_s) const {
  std::size_t n = 0;
  for (std::size_t k = next_time_; k < times_.size() && times_[k] <= until_s; ++k)
    if (every_s_ <= 0.0 || times_[k] < next_multiple_ * every_s_ || std::fmod(times_[k], every_s_) != 0.0) ++n;
  if (every_s_ > 0.0 && until_s >= next_multiple_ * every_s_) {
    auto last = static_cast<long long>(std::floor(until_s / every_s_));
    while (last * every_s_ > until_s) --last;
    while ((last + 1) * every_s_ <= until_s) ++last;
    n += std::size_t(last - next_multiple_ + 1);
  }
  return n;
}

}  // namespace ig::session
