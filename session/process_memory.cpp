#include "session/process_memory.h"

#include <malloc.h>

#include <fstream>
#include <optional>
#include <sstream>
#include <string>

namespace ig::session {
namespace {
// A "Key:  value kB" line of /proc/self/status, in MB.
std::optional<double> status_mb(const std::string& wanted) {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    std::istringstream fields(line);
    std::string key;
    double kb = 0;
    if (fields >> key >> kb && key == wanted) return kb / 1024.0;
  }
  return std::nullopt;
}
}  // namespace

double resident_mb() { return status_mb("VmRSS:").value_or(0.0); }

nlohmann::json process_memory() {
  constexpr double kMb = 1024.0 * 1024.0;
  nlohmann::json out = nlohmann::json::object();
  if (const auto rss = status_mb("VmRSS:")) out["rss_mb"] = *rss;
  if (const auto peak = status_mb("VmHWM:")) out["peak_rss_mb"] = *peak;
  const struct mallinfo2 m = mallinfo2();
  out["heap_in_use_mb"] = double(m.uordblks + m.hblkhd) / kMb;
  out["heap_free_mb"] = double(m.fordblks) / kMb;
  out["heap_mmapped_mb"] = double(m.hblkhd) / kMb;
  return out;
}

}  // namespace ig::session
