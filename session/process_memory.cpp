#include "session/process_memory.h"

#include <malloc.h>

#include <fstream>
#include <sstream>
#include <string>

namespace ig::session {

nlohmann::json process_memory() {
  constexpr double kMb = 1024.0 * 1024.0;
  nlohmann::json out = nlohmann::json::object();
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    std::istringstream fields(line);
    std::string key;
    double kb = 0;
    if (!(fields >> key >> kb)) continue;
    if (key == "VmRSS:") out["rss_mb"] = kb / 1024.0;
    if (key == "VmHWM:") out["peak_rss_mb"] = kb / 1024.0;
  }
  const struct mallinfo2 m = mallinfo2();
  out["heap_in_use_mb"] = double(m.uordblks + m.hblkhd) / kMb;
  out["heap_free_mb"] = double(m.fordblks) / kMb;
  out["heap_mmapped_mb"] = double(m.hblkhd) / kMb;
  return out;
}

}  // namespace ig::session
