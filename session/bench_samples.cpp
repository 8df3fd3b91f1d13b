#include "session/bench_samples.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace ig::session {
namespace {

// Small relative errors need more digits than the CSV's fixed 4 decimals.
std::string g6(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

std::vector<stats::Cell> BenchSamples::add(const stats::ImageError& e, std::optional<double> bound_px,
                                           const std::optional<TemporalSample>& temporal) {
  ++n_;
  horizon_sum_ += e.horizon_mean_px;
  horizon_max_ = std::max(horizon_max_, e.horizon_max_px);
  depth_p95_.push_back(e.depth_rel_p95);
  depth_max_ = std::max(depth_max_, e.depth_rel_max);
  sq_sum_ += e.mse * 3.0 * pixels_;
  samples_px_ += 3.0 * pixels_;
  holes_ += double(e.holes);
  interior_holes_ += double(e.interior_holes);
  enclosed_holes_ += double(e.enclosed_holes);
  ref_px_ += double(e.reference_terrain_pixels);
  if (bound_px) bounds_.push_back(*bound_px);
  if (temporal) temporal_.push_back({temporal->time_s, temporal->error.mean});
  auto temporal_cell = [&](const char* name, double v) {
    return temporal ? stats::Cell(name, g6(v)) : stats::Cell(name, std::string());
  };
  return {{"horizon_mean_px", e.horizon_mean_px},
          {"horizon_max_px", e.horizon_max_px},
          {"horizon_columns", e.horizon_columns},
          {"depth_rel_p95", g6(e.depth_rel_p95)},
          {"depth_rel_max", g6(e.depth_rel_max)},
          {"psnr_db", e.psnr_db},
          {"holes", e.holes},
          {"interior_holes", e.interior_holes},
          {"enclosed_holes", e.enclosed_holes},
          {"reference_terrain_px", e.reference_terrain_pixels},
          bound_px ? stats::Cell("bound_px", *bound_px) : stats::Cell("bound_px", std::string()),
          temporal ? stats::Cell("frame_before", temporal->frame_before) : stats::Cell("frame_before", std::string()),
          temporal_cell("temporal_error", temporal ? temporal->error.mean : 0.0),
          temporal_cell("method_change", temporal ? temporal->error.method_change : 0.0),
          temporal_cell("reference_change", temporal ? temporal->error.reference_change : 0.0)};
}

void BenchSamples::finish(BenchRow& row) const {
  const int n = n_;
  row.error_samples = n;
  row.horizon_mean_px = n ? horizon_sum_ / n : 0.0;
  row.horizon_max_px = horizon_max_;
  row.depth_rel_p95 = stats::percentiles(depth_p95_).median;
  row.depth_rel_max = depth_max_;
  row.psnr_db = stats::psnr_db_from_mse(samples_px_ > 0 ? sq_sum_ / samples_px_ : 0.0, samples_px_);
  row.holes_mean = n ? holes_ / n : 0.0;
  row.interior_holes_mean = n ? interior_holes_ / n : 0.0;
  row.enclosed_holes_mean = n ? enclosed_holes_ / n : 0.0;
  row.hole_fraction = ref_px_ > 0 ? holes_ / ref_px_ : 0.0;
  if (!bounds_.empty() && int(bounds_.size()) == n) {
    row.bound_px_median = stats::percentiles(bounds_).median;
    row.bound_px_max = stats::percentiles(bounds_).max;
  }
  row.temporal_pairs = int(temporal_.size());
  row.temporal_error_by_time = temporal_;
  double sum = 0.0, max = 0.0;
  for (const auto& [t, v] : temporal_) {
    sum += v;
    max = std::max(max, v);
  }
  row.temporal_error_mean = temporal_.empty() ? 0.0 : sum / double(temporal_.size());
  row.temporal_error_max = max;
}

}  // namespace ig::session
