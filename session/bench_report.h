#pragma once
// What ig bench leaves behind: results.csv (one row per method and knob
// value), results.md (the same as a table plus the run's context and the
// matched-horizon-error table), error_vs_time.png and temporal_error.png
// (gnuplot). Column and metric definitions: docs/bench.md.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/terrain_method.h"

namespace ig::session {

// One method at one knob value, measured along the whole flight.
struct BenchRow {
  std::string method;
  std::optional<render::ErrorKnob> knob;  // nullopt: the method has none
  bool default_knob = true;               // the setting make_method picks without a knob
  double build_ms = 0.0;                  // make_method (e.g. Level0 build)
  int frames = 0;
  double frame_ms_median = 0.0, frame_ms_p95 = 0.0;
  double lod_ms_median = 0.0;
  double triangles_median = 0.0;
  // Hardware-independent work per frame (medians): shader invocations and
  // primitives from pipeline statistics queries, draw calls, bytes uploaded.
  double vs_invocations_median = 0.0, fs_invocations_median = 0.0, primitives_median = 0.0;
  double draw_calls_median = 0.0, upload_bytes_median = 0.0;
  // Process CPU time per frame (all threads, llvmpipe's rasteriser included).
  double cpu_ms_median = 0.0;
  double cores_median = 0.0;  // per frame CPU / wall: cores the frame keeps busy
  // Samples that passed the depth test per pixel, every pass (the fragments
  // an early-z GPU shades; llvmpipe's fs_invocations count every rasterized one).
  double passed_per_pixel_median = 0.0;
  // Boxes (blocks, chunks, nodes, triangle groups, clusters) left out by
  // horizon culling per frame (the method's hidden_boxes column; 0 without).
  double hidden_boxes_median = 0.0;
  // Pipelined (ig bench --pipelined): frames issued while the one before is
  // still drawn. Frame ms: from one frame's issue to the next one's (what
  // the IG sustains); CPU ms over the same interval; latency: from issue to
  // seen done. 0 frames: not flown pipelined.
  int pipelined_frames = 0;
  double pipelined_frame_ms_median = 0.0, pipelined_frame_ms_p95 = 0.0;
  double pipelined_cpu_ms_median = 0.0, pipelined_latency_ms_median = 0.0, pipelined_lod_ms_median = 0.0;
  int error_samples = 0;
  double horizon_mean_px = 0.0;  // mean over samples of each frame's column mean
  double horizon_max_px = 0.0;   // max over samples
  double depth_rel_p95 = 0.0;    // median over samples of each frame's p95
  double depth_rel_max = 0.0;    // max over samples
  double psnr_db = 0.0;          // from the MSE pooled over every sample
  double holes_mean = 0.0;       // holes per sampled frame
  double hole_fraction = 0.0;    // holes / reference terrain pixels, all samples
  double interior_holes_mean = 0.0;
  double enclosed_holes_mean = 0.0;  // sky through the surface (cracks), per sampled frame
  std::optional<double> bound_px_median, bound_px_max;  // nullopt: the method claims no bound
  // Temporal error (popping), per pair (frame rendered just before a sample,
  // the sample): mean over pixels of |(M_k - M_k-1) - (R_k - R_k-1)|, luma levels.
  int temporal_pairs = 0;
  double temporal_error_mean = 0.0;  // mean over the pairs
  double temporal_error_max = 0.0;   // largest pair
  std::vector<std::pair<double, double>> temporal_error_by_time;  // (scenario time s of the sample, its error)
};

// Where a method's frame time at the target horizon error comes from.
enum class MatchKind {
  Measured,      // a point lies at the target: its own time
  Interpolated,  // the target lies between two neighbouring sweep points
  AtMost,        // every point is more accurate than the target: its cheapest point's time bounds it
  NotReached,    // no point is that accurate: more than its most accurate point's time
};

struct MatchedRow {
  std::string method;
  MatchKind kind = MatchKind::Interpolated;
  double frame_ms = 0.0;
  // method ms / twolevel ms at the target (how many times faster twolevel is);
  // nullopt when twolevel's own time at the target is neither measured nor interpolated.
  std::optional<double> ratio;
};

// Each method's median frame time at `target_px` mean horizon error: a row at
// the target gives its own time; otherwise walk the rows in sweep order
// (least to most accurate) and interpolate linearly in (horizon_mean_px,
// frame_ms_median) between neighbours that bracket the target (the smallest
// such time when the curve crosses it more than once).
// `time` picks the time measure: the wall-clock frame time, or the CPU time.
std::vector<MatchedRow> match_horizon_error(const std::vector<BenchRow>& rows, double target_px,
                                            double BenchRow::*time = &BenchRow::frame_ms_median);

// The run's context for results.md.
struct BenchContext {
  std::string command_line;
  std::string scenario_name, scenario_file;
  std::string gl_renderer, gl_version, cpu, host;
  std::string terrain;  // e.g. "file.tif (4097x4097 samples, 73.5 x 92.6 m)"
  int width = 0, height = 0;
  double fov_y_deg = 0.0;
  int frames = 0, scenario_frames = 0;
  double time_step_s = 0.0;
  std::vector<int> frame_indices;   // the scenario frames rendered
  std::vector<int> sample_indices;  // of which these were compared with the reference
  std::vector<int> temporal_before_indices;  // the frames rendered just before a sample (its temporal pair)
  double wall_s = 0.0;
  bool sweep = false;
  bool interleaved = false;  // every frame flown by every method and knob in turn, not one after the other
  bool pipelined = false;    // every frame flown again with frames in flight (BenchRow::pipelined_*)
};

void write_bench_csv(const std::string& path, const std::vector<BenchRow>& rows);
// `target_px`: nullopt when there is no target (no twolevel row and no --match-px).
void write_bench_markdown(const std::string& path, const BenchContext& context, const std::vector<BenchRow>& rows,
                          std::optional<double> target_px, const std::string& target_source);
// Returns false (and says why on stderr) when gnuplot is missing or fails.
bool plot_error_vs_time(const std::string& png_path, const std::vector<BenchRow>& rows,
                        std::optional<double> target_px, const std::string& title);
// Temporal error against scenario time, one curve per method at its default
// knob (a sweep's other values are in results.csv and samples.csv). Returns
// false as plot_error_vs_time does.
bool plot_temporal_error(const std::string& png_path, const std::vector<BenchRow>& rows, const std::string& title);

}  // namespace ig::session
