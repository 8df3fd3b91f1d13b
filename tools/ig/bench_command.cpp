// ig bench SCENARIO.json: every LOD method (and with --sweep every value of
// its error knob) flown along the same scenario path with the same size and
// camera; frame time against image error versus the reference renderer.
// Writes results.csv, results.md, error_vs_time.png, temporal_error.png,
// frames.csv and samples.csv (docs/bench.md).
//
// The terrain is loaded once (ScenarioRunner, as for ig run) and its
// TerrainScene shared by every method. The runner's own method is the
// reference: it renders the sampled frames (and the frame before each, for
// the temporal error) first and they are kept on the CPU, so the timed runs
// are never interrupted by a reference render.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>

#include "bench_variant_run.h"
#include "cli_args.h"
#include "commands.h"
#include "gl/shader_program.h"
#include "session/bench_report.h"
#include "session/scenario_runner.h"
#include "stats/frame_log.h"
#include "stats/image_error.h"
#include "stats/timing.h"

namespace ig::app {
namespace {
using session::BenchRow;
using session::BenchContext;
using session::MatchedRow;
using session::write_bench_csv;
using session::write_bench_markdown;
using session::plot_error_vs_time;
using session::plot_temporal_error;
using session::match_horizon_error;

constexpr const char* kUsage =
    "usage: ig bench SCENARIO.json [--methods LIST|all] [--sweep] [--frames N] [--size WxH] [--fov DEG]\n"
    "                [--error-samples N] [--match-px PX] [--skip-pass NAME] [--interleave] [--pipelined]\n"
    "                [--shader-dir DIR] [--out DIR]\n"
    "Flies every LOD method along the scenario's path and reports frame time against image error\n"
    "versus the reference renderer (docs/bench.md): results.csv, results.md, error_vs_time.png,\n"
    "temporal_error.png.\n"
    "Exit status: 0 ok, 1 the run failed (or the plot could not be drawn), 2 bad arguments.\n";

using Clock = stats::WallClock;
using stats::ms_since;

struct Args {
  std::string scenario;
  std::vector<std::string> methods;
  bool sweep = false;
  std::optional<int> frames;
  session::RunOptions run;  // --size (and the reference method, headless)
  std::optional<double> fov;
  int error_samples = 10;
  std::optional<double> match_px;
  std::vector<std::string> skip_passes;  // --skip-pass (twolevel cost breakdown)
  std::string horizon_culling;           // --horizon-culling on|off for every method ("": the scenario's)
  bool interleave = false;               // every frame flown by every variant in turn
  bool pipelined = false;                // every frame flown again with frames in flight
  std::string shader_dir;
  std::string out_dir;
  std::string command_line;  // as typed, for the report
};

std::vector<std::string> split_methods(const std::string& list) {
  const auto known = render::method_names();
  std::vector<std::string> out;
  if (list == "all") return known;
  size_t start = 0;
  while (start <= list.size()) {
    const size_t comma = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, comma - start);
    if (name.empty()) throw UsageError("--methods: empty name in '" + list + "'");
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::string choices;
      for (const auto& n : known) choices += (choices.empty() ? "" : ", ") + n;
      throw UsageError("--methods: unknown method '" + name + "' (available: " + choices + ", or all)");
    }
    if (std::find(out.begin(), out.end(), name) != out.end())
      throw UsageError("--methods: '" + name + "' given twice");
    out.push_back(name);
    start = comma + 1;
  }
  return out;
}

std::string command_line(const std::vector<std::string>& argv) {
  std::string s = "ig bench";
  for (const auto& a : argv) s += " " + (a.find_first_of(" \t'\"") == std::string::npos ? a : "'" + a + "'");
  return s;
}

Args parse_args(const std::vector<std::string>& a) {
  Args args;
  CLI::App app("ig bench");
  std::optional<std::string> methods;
  add_scenario_argument(app, args.scenario, "the scenario whose path every method flies (docs/scenario.md)");
  app.add_option("--methods", methods, "comma-separated method names, or all (default: all)")->option_text("LIST");
  app.add_flag("--sweep", args.sweep,
               "every knob value of each method's sweep (default: each method at its default knob only)");
  add_count_option(app, "--frames", args.frames,
                   "N frames spread evenly over the flight, first and last included (default: every scenario frame)");
  add_size_option(app, "--size", args.run.width, args.run.height)
      ->description("image size in pixels (default: the scenario's)")
      ->option_text("WxH");
  app.add_option("--fov", args.fov, "vertical field of view, degrees in (0, 179] (default: the scenario's)")
      ->check(positive_number())
      ->option_text("DEG");
  add_count_option(app, "--error-samples", args.error_samples,
                   "frames compared with the reference, spread evenly over the timed ones (default 10)");
  app.add_option("--match-px", args.match_px,
                 "horizon error in pixels for the matched-error table (default: the two-level method's at its "
                 "default knob)")
      ->check(positive_number())
      ->option_text("PX");
  app.add_option("--skip-pass", args.skip_passes,
                 "cost breakdown: the two-level method draws without its pass NAME (level1, band, level0, "
                 "count); repeatable. The images are then wrong on purpose")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)->expected(1)->allow_extra_args(false)
      ->option_text("NAME");
  app.add_option("--horizon-culling", args.horizon_culling,
                 "on or off for every method: what each draws behind nearer terrain is left out (default: the "
                 "scenario's, on)")
      ->check(CLI::IsMember({"on", "off"}))
      ->option_text("on|off");
  app.add_flag("--interleave", args.interleave,
               "fly every frame with every method and knob in turn (all built first), so that a drift of the "
               "machine's speed or the GPU's clock during the run reaches them alike (default: one after the "
               "other)");
  app.add_flag("--pipelined", args.pipelined,
               "fly every frame a second time pipelined, each issued while the one before is still drawn (as a "
               "live IG with frames in flight runs), in stretches of consecutive frames taken in turn by every "
               "method and knob: frame interval, CPU time and latency in results.md and frames_pipelined.csv "
               "(default: only each frame finished before the next)");
  add_shader_dir_option(app, args.shader_dir);
  app.add_option("--out", args.out_dir, "output folder (default out/<scenario>_bench)")->option_text("DIR");
  parse_command_line(app, a);
  if (args.scenario.empty()) throw UsageError("missing SCENARIO.json");
  if (args.run.width > 16384 || args.run.height > 16384) throw UsageError("--size: at most 16384x16384");
  if (args.fov > 179.0) throw UsageError("--fov: must be in (0, 179] degrees");
  args.methods = methods ? split_methods(*methods) : render::method_names();
  args.command_line = command_line(a);
  return args;
}

// N indices spread evenly over [0, total) including both ends (all when N >= total).
std::vector<int> spread_frames(int total, std::optional<int> n) {
  std::vector<int> out;
  if (!n || *n >= total) {
    for (int k = 0; k < total; ++k) out.push_back(k);
  } else if (*n == 1) {
    out.push_back(0);
  } else {
    for (int i = 0; i < *n; ++i) out.push_back(int(std::lround(double(i) * (total - 1) / (*n - 1))));
  }
  return out;
}

// Positions (into the rendered frames) of the M sampled frames: the centres
// of M equal bins, which keeps clear of the very first frame.
std::vector<int> sample_positions(int frames, int m) {
  m = std::min(m, frames);
  std::vector<int> out;
  for (int j = 0; j < m; ++j) out.push_back(int(std::floor((j + 0.5) * frames / m)));
  return out;
}

std::string cpu_description() {
  std::ifstream in("/proc/cpuinfo");
  std::string line, model;
  int threads = 0;
  while (std::getline(in, line)) {
    if (line.rfind("processor", 0) == 0) ++threads;
    if (model.empty() && line.rfind("model name", 0) == 0) {
      const auto c = line.find(':');
      if (c != std::string::npos) model = line.substr(c + 2);
    }
  }
  if (model.empty()) model = "unknown CPU";
  return model + ", " + std::to_string(threads) + " hardware threads";
}

std::string host_name() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0) return "unknown";
  return buf;
}

// Progress on stderr: a bar redrawn in place on a terminal, one line per
// method and knob otherwise (logs stay readable).
class Progress {
 public:
  Progress(bool tty, long long total) : tty_(tty), total_(std::max(total, 1LL)) {}
  void step(const std::string& label, int frame, int frames) {
    ++done_;
    if (!tty_) return;
    constexpr int kBar = 30;
    const int filled = int(kBar * double(done_) / double(total_));
    std::fprintf(stderr, "\rig bench [%s%s] %3d%%  %-36s frame %d/%d   ", std::string(filled, '#').c_str(),
                 std::string(kBar - filled, '.').c_str(), int(100.0 * done_ / total_), label.c_str(), frame, frames);
    std::fflush(stderr);
  }
  void line(const std::string& text) {
    if (tty_) std::fprintf(stderr, "\r%-100s\r", "");
    std::fprintf(stderr, "ig bench: %s\n", text.c_str());
  }
  void finish() {
    if (tty_) std::fprintf(stderr, "\r%-100s\r", "");
  }

 private:
  bool tty_;
  long long total_, done_ = 0;
};

// ig bench with its parsed arguments: the exit status.
int run(const Args& args) {
  const auto start = Clock::now();
  io::Scenario scenario = io::load_scenario(args.scenario);
  namespace fs = std::filesystem;
  const fs::path out = args.out_dir.empty() ? fs::path("out") / (scenario.name + "_bench") : fs::path(args.out_dir);
  fs::create_directories(out);

  // The first channel only; --fov replaces the scenario's (and that channel's own) field of view.
  scenario.channels.resize(1);
  if (args.fov) {
    scenario.render.fov_y_deg = *args.fov;
    scenario.channels[0].fov_y_deg.reset();
  }
  session::RunOptions run = args.run;
  run.method = "reference";
  run.headless = true;
  run.shader_dir = args.shader_dir.empty() ? gl::default_shader_dir() : args.shader_dir;
  session::ScenarioRunner runner(std::move(scenario), run);
  const auto& s = runner.scenario();
  const auto& hf = runner.heightfield();
  const int width = s.render.width, height = s.render.height;
  render::MethodOptions method_options = s.render.method_options();
  method_options.twolevel.skip_passes = args.skip_passes;
  if (!args.horizon_culling.empty()) method_options.set_horizon_culling(args.horizon_culling == "on");

  const std::vector<int> frames = spread_frames(runner.frame_count(), args.frames);
  const std::vector<int> sample_pos = sample_positions(int(frames.size()), args.error_samples);
  // The temporal error pairs each sample with the frame rendered just before
  // it: adjacent frames, so it measures popping between consecutive images
  // (the samples themselves are spread over the flight).
  std::set<int> before_pos, image_pos(sample_pos.begin(), sample_pos.end());
  for (int p : sample_pos)
    if (p > 0) before_pos.insert(p - 1), image_pos.insert(p - 1);
  std::vector<Variant> variants;
  for (const auto& m : args.methods)
    for (auto& v : variants_for(m, args.sweep, method_options)) variants.push_back(v);

  Progress progress(isatty(STDERR_FILENO) != 0,
                    (long long)image_pos.size() + (long long)variants.size() * (long long)frames.size());

  // Reference frames for the sampled frames and the frames before them,
  // rendered once, in order, and kept (the frames before only as luma).
  auto& ref_channel = runner.channels().front();
  std::map<int, stats::FrameImage> reference;  // by position in `frames`
  std::map<int, stats::LumaImage> reference_luma;
  std::map<int, render::Camera> reference_camera;
  {
    const auto t0 = Clock::now();
    for (int p : image_pos) {
      runner.render_frame(frames[p]);
      stats::FrameImage img = stats::read_frame_image(*ref_channel.target);
      reference_luma[p] = stats::luminance(img);
      if (std::find(sample_pos.begin(), sample_pos.end(), p) != sample_pos.end()) reference[p] = std::move(img);
      reference_camera[p] = ref_channel.camera;
      progress.step("reference images", int(reference_luma.size()), int(image_pos.size()));
    }
    char buf[160];
    std::snprintf(buf, sizeof buf, "%zu reference frames at %dx%d in %.1f s", image_pos.size(), width, height,
                  ms_since(t0) / 1000.0);
    progress.line(buf);
  }

  auto camera_at = [&](int frame) {
    return runner.camera_for(runner.pose_at(frame * s.time_step_s), ref_channel);
  };
  const auto target_ptr = session::make_frame_target(s.render, width, height);  // as the reference's
  stats::FrameLog frames_csv((out / "frames.csv").string());
  stats::FrameLog samples_csv((out / "samples.csv").string());
  BenchFlight flight;
  flight.scene = &runner.scene();
  flight.shader_dir = run.shader_dir;
  flight.method_options = method_options;
  flight.frames = frames;
  flight.sample_pos = sample_pos;
  flight.before_pos = before_pos;
  flight.reference = std::move(reference);
  flight.reference_luma = std::move(reference_luma);
  flight.reference_camera = std::move(reference_camera);
  flight.camera_at = camera_at;
  flight.target = target_ptr.get();
  flight.width = width;
  flight.height = height;
  flight.time_step_s = s.time_step_s;
  flight.frames_csv = &frames_csv;
  flight.samples_csv = &samples_csv;
  std::optional<stats::FrameLog> pipelined_csv;
  if (args.pipelined) flight.pipelined_csv = &pipelined_csv.emplace((out / "frames_pipelined.csv").string());

  std::vector<BenchRow> rows;
  auto report = [&](const VariantRun& r, const BenchRow& row) {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "%-36s %d frames: median %.2f ms, p95 %.2f ms, horizon mean %.3f px, max %.0f px, temporal "
                  "%.3f (%.1f s)",
                  r.label().c_str(), row.frames, row.frame_ms_median, row.frame_ms_p95, row.horizon_mean_px,
                  row.horizon_max_px, row.temporal_error_mean, r.seconds());
    progress.line(buf);
  };
  const int n_frames = int(frames.size());
  // Pipelined: the frames again in stretches of consecutive positions, each
  // stretch flown by every run in turn (the first rotating) and drained
  // before the next run's, so a drift of the machine reaches them alike.
  constexpr int kStretch = 10;
  auto fly_pipelined = [&](const std::vector<VariantRun*>& runs) {
    if (!args.pipelined) return;
    const int n = int(runs.size());
    for (int i0 = 0, s = 0; i0 < n_frames; i0 += kStretch, ++s)
      for (int k = 0; k < n; ++k) {
        VariantRun& r = *runs[(s + k) % n];
        for (int i = i0; i < std::min(i0 + kStretch, n_frames); ++i) r.fly_pipelined(i);
        r.end_pipelined();
      }
  };
  if (!args.interleave) {
    for (const Variant& v : variants) {
      VariantRun r(v, flight);
      r.warm_up();
      for (int i = 0; i < n_frames; ++i) {
        r.fly(i);
        progress.step(r.label(), i + 1, n_frames);
      }
      fly_pipelined({&r});
      rows.push_back(r.finish());
      report(r, rows.back());
    }
  } else {
    // Every variant built first; then each frame flown by all of them, the
    // first of them rotating so that none always follows the same one.
    std::vector<std::unique_ptr<VariantRun>> runs;
    for (const Variant& v : variants) runs.push_back(std::make_unique<VariantRun>(v, flight));
    for (auto& r : runs) r->warm_up();
    const int n = int(runs.size());
    for (int i = 0; i < n_frames; ++i)
      for (int k = 0; k < n; ++k) {
        VariantRun& r = *runs[(i + k) % n];
        r.fly(i);
        progress.step(r.label(), i + 1, n_frames);
      }
    std::vector<VariantRun*> all;
    for (auto& r : runs) all.push_back(r.get());
    fly_pipelined(all);
    for (auto& r : runs) {
      rows.push_back(r->finish());
      report(*r, rows.back());
    }
  }
  progress.finish();

  // The matched-error target: --match-px, else the two-level method's default.
  std::optional<double> match_target = args.match_px;
  std::string target_source = "--match-px";
  if (!match_target)
    for (const auto& r : rows)
      if (r.method == "twolevel" && r.default_knob) {
        match_target = r.horizon_mean_px;
        target_source = "the two-level method's default setting";
      }

  BenchContext c;
  c.command_line = args.command_line;
  c.scenario_name = s.name;
  c.scenario_file = args.scenario;
  c.gl_renderer = runner.context().gl_renderer();
  c.gl_version = runner.context().gl_version();
  c.cpu = cpu_description();
  c.host = host_name();
  char terrain[512];
  std::snprintf(terrain, sizeof terrain, "%s (%dx%d samples, %.1f x %.1f m spacing, loaded in %.0f ms)",
                hf.source.c_str(), hf.width, hf.height, hf.spacing_x_m, hf.spacing_y_m, runner.load_ms());
  c.terrain = terrain;
  c.width = width;
  c.height = height;
  c.fov_y_deg = ref_channel.spec.fov_y_deg.value_or(s.render.fov_y_deg);
  c.frames = int(frames.size());
  c.scenario_frames = runner.frame_count();
  c.time_step_s = s.time_step_s;
  c.frame_indices = frames;
  for (int p : sample_pos) c.sample_indices.push_back(frames[p]);
  for (int p : before_pos) c.temporal_before_indices.push_back(frames[p]);
  c.sweep = args.sweep;
  c.interleaved = args.interleave;
  c.pipelined = args.pipelined;
  c.wall_s = ms_since(start) / 1000.0;

  write_bench_csv((out / "results.csv").string(), rows);
  write_bench_markdown((out / "results.md").string(), c, rows, match_target, target_source);
  const bool plotted = plot_error_vs_time((out / "error_vs_time.png").string(), rows, match_target,
                                          s.name + " / " + std::to_string(width) + "x" + std::to_string(height) +
                                              " / FOV " + std::to_string(int(std::lround(c.fov_y_deg))) + " / " +
                                              c.gl_renderer);
  const bool plotted_temporal = plot_temporal_error(
      (out / "temporal_error.png").string(), rows,
      s.name + " / " + std::to_string(width) + "x" + std::to_string(height) + " / temporal error, default knobs");
  std::printf("ig bench: %s, %zu method/knob rows x %d frames at %dx%d, FOV %g, on %s in %.1f s\n", s.name.c_str(),
              rows.size(), c.frames, width, height, c.fov_y_deg, c.gl_renderer.c_str(), ms_since(start) / 1000.0);
  std::printf("ig bench: outputs in %s (results.csv, results.md, frames.csv, samples.csv%s%s)\n",
              out.string().c_str(), plotted ? ", error_vs_time.png" : "", plotted_temporal ? ", temporal_error.png" : "");
  return plotted && plotted_temporal ? 0 : 1;
}

}  // namespace

int run_bench_command(const std::vector<std::string>& argv) {
  return run_command("ig bench", kUsage, parse_args, argv, run);
}

}  // namespace ig::app
