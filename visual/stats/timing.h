#pragma once
// The two clocks a benchmark reads: wall time since a point, and CPU time
// of the whole process (every thread: llvmpipe rasterises on its own, so a
// frame's CPU work shows here and not in the wall clock alone).

#include <chrono>
#include <ctime>

namespace ig::stats {

using WallClock = std::chrono::steady_clock;

inline double ms_since(WallClock::time_point t0) {
  return std::chrono::duration<double, std::milli>(WallClock::now() - t0).count();
}

inline double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

}  // namespace ig::stats
