#pragma once
// Returns the C library's free heap pages to the system at most once every
// `every_s` seconds, for long runs. Memory the renderer frees after a frame
// stays in malloc's free lists at the size of the largest frame so far (with
// llvmpipe, resident memory steps up at each new largest frame and never comes
// down; presumably its per-frame binning memory, not traced in Mesa's
// source); trimming gives those pages back. It cost 1-2 ms a trim on the
// development VM (up to 15 ms overloaded); the live loop calls it after a
// frame is sent.

#include <nlohmann/json.hpp>

namespace ig::session {

class HeapTrim {
 public:
  explicit HeapTrim(double every_s) : every_s_(every_s) {}
  // Trims when `now_s` is every_s or more after the last trim (or the first
  // call). Returns whether it trimmed.
  bool maybe_trim(double now_s);
  // Trims now.
  void trim();
  // trims, ms_total, ms_max, released_mb (resident memory before minus after, summed).
  nlohmann::json summary() const;

 private:
  double every_s_;
  double last_s_ = -1e300;
  int trims_ = 0;
  double ms_total_ = 0.0, ms_max_ = 0.0, released_mb_ = 0.0;
};

}  // namespace ig::session
