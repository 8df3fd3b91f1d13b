#pragma once
// The error samples of one method at one knob value in ig bench: each
// sampled frame's image error against the reference and, where the frame
// rendered just before it was read back too, the temporal error of that
// pair; pooled into the BenchRow's error columns, and one samples.csv row
// per sampled frame. Definitions: docs/bench.md.

#include <optional>
#include <vector>

#include "session/bench_report.h"
#include "stats/frame_log.h"
#include "stats/image_error.h"
#include "stats/temporal_error.h"

namespace ig::session {

// The pair (frame rendered before, sampled frame) of one temporal sample.
struct TemporalSample {
  int frame_before = 0;  // scenario frame index of the earlier image
  double time_s = 0.0;   // scenario time of the sampled (later) frame
  stats::TemporalError error;
};

class BenchSamples {
 public:
  // Images of width x height pixels.
  BenchSamples(int width, int height) : pixels_(double(width) * double(height)) {}

  // Adds one sampled frame (`bound_px`: the method's error_bound_px, nullopt
  // when it claims none; `temporal`: nullopt when no earlier frame was
  // rendered) and returns its samples.csv cells, to follow the row's own
  // method, knob, frame and time cells.
  std::vector<stats::Cell> add(const stats::ImageError& e, std::optional<double> bound_px,
                               const std::optional<TemporalSample>& temporal);

  // Fills the row's error columns from every sample added.
  void finish(BenchRow& row) const;

 private:
  double pixels_;
  int n_ = 0;
  double horizon_sum_ = 0.0, horizon_max_ = 0.0, depth_max_ = 0.0, sq_sum_ = 0.0, samples_px_ = 0.0;
  double holes_ = 0.0, interior_holes_ = 0.0, enclosed_holes_ = 0.0, ref_px_ = 0.0;
  std::vector<double> depth_p95_, bounds_;
  std::vector<std::pair<double, double>> temporal_;  // (time s, mean)
};

}  // namespace ig::session
