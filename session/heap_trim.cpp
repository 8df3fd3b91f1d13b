#include "session/heap_trim.h"

#include <malloc.h>

#include <algorithm>
#include <chrono>

#include "session/process_memory.h"

namespace ig::session {

bool HeapTrim::maybe_trim(double now_s) {
  if (now_s - last_s_ < every_s_) return false;
  last_s_ = now_s;
  trim();
  return true;
}

void HeapTrim::trim() {
  const double before = resident_mb();
  const auto t0 = std::chrono::steady_clock::now();
  malloc_trim(0);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const double after = resident_mb();
  ++trims_;
  ms_total_ += ms;
  ms_max_ = std::max(ms_max_, ms);
  released_mb_ += std::max(0.0, before - after);
}

nlohmann::json HeapTrim::summary() const {
  return {{"every_s", every_s_}, {"trims", trims_}, {"ms_total", ms_total_}, {"ms_max", ms_max_},
          {"released_mb", released_mb_}};
}

}  // namespace ig::session
