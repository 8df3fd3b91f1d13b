// ig run SCENARIO.json: replay a scenario to the end and leave its outputs
// (frames.csv, summary.json, captured PNGs, final.png, frametime.png).
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

#include <nlohmann/json.hpp>

#include "capture/png_writer.h"
#include "commands.h"
#include "frametime_plot.h"
#include "scenario_runner.h"

namespace ig::app {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

constexpr const char* kUsage =
    "usage: ig run SCENARIO.json [--out DIR] [--frames N] [--size WxH] [--method NAME]\n"
    "              [--headless | --window [--fullscreen] [--vsync on|off]] [--shader-dir DIR] [--quiet]\n";

struct Args {
  std::string scenario;
  std::string out_dir;
  RunOptions run;
  bool quiet = false;
};

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

int parse_int(const std::string& flag, const std::string& v) {
  size_t used = 0;
  int n = 0;
  try {
    n = std::stoi(v, &used);
  } catch (...) {
    used = 0;
  }
  if (used != v.size() || n <= 0) throw UsageError(flag + ": expected a positive integer, got '" + v + "'");
  return n;
}

Args parse_args(const std::vector<std::string>& a) {
  Args args;
  args.run.headless = true;
  bool window = false, headless = false;
  for (size_t k = 0; k < a.size(); ++k) {
    const std::string& f = a[k];
    auto value = [&]() -> const std::string& {
      if (k + 1 >= a.size()) throw UsageError(f + ": missing value");
      return a[++k];
    };
    if (f == "--out") args.out_dir = value();
    else if (f == "--frames") args.run.frames = parse_int(f, value());
    else if (f == "--size") {
      const std::string v = value();
      const auto x = v.find('x');
      if (x == std::string::npos) throw UsageError("--size: expected WxH, got '" + v + "'");
      args.run.width = parse_int(f, v.substr(0, x));
      args.run.height = parse_int(f, v.substr(x + 1));
    } else if (f == "--method") args.run.method = value();
    else if (f == "--headless") headless = true;
    else if (f == "--window") window = true;
    else if (f == "--fullscreen") args.run.fullscreen = window = true;
    else if (f == "--vsync") {
      const std::string v = value();
      if (v != "on" && v != "off") throw UsageError("--vsync: expected on or off");
      args.run.vsync = v == "on";
    } else if (f == "--shader-dir") args.run.shader_dir = value();
    else if (f == "--quiet") args.quiet = true;
    else if (!f.empty() && f[0] == '-') throw UsageError("unknown option " + f);
    else if (args.scenario.empty()) args.scenario = f;
    else throw UsageError("unexpected argument " + f);
  }
  if (args.scenario.empty()) throw UsageError("missing SCENARIO.json");
  if (window && headless) throw UsageError("--window and --headless exclude each other");
  args.run.headless = !window;
  return args;
}

std::string capture_name(const ChannelView& ch, int frame, double t) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "capture_%s_t%07.3fs_f%06d.png", ch.spec.name.c_str(), t, frame);
  return buf;
}

}  // namespace

int run_run_command(const std::vector<std::string>& argv) {
  Args args;
  try {
    args = parse_args(argv);
  } catch (const UsageError& e) {
    std::cerr << "ig run: " << e.what() << "\n" << kUsage;
    return 2;
  }
  try {
    io::Scenario scenario = io::load_scenario(args.scenario);
    namespace fs = std::filesystem;
    const fs::path out = args.out_dir.empty() ? fs::path("out") / scenario.name : fs::path(args.out_dir);
    fs::create_directories(out);

    ScenarioRunner runner(std::move(scenario), args.run);
    const auto& s = runner.scenario();
    const int frames = runner.frame_count();

    // Frames to capture: the nearest frame to each capture time inside the run.
    std::set<int> capture_frames;
    for (double t : s.capture_times_s)
      if (const int k = std::min(int(std::lround(t / s.time_step_s)), io::scenario_frame_count(s) - 1); k < frames)
        capture_frames.insert(k);

    stats::FrameLog log((out / "frames.csv").string());
    std::vector<std::string> captured;
    const bool progress = !args.quiet && isatty(STDERR_FILENO);
    const auto run_start = Clock::now();
    int rendered = 0;
    for (int k = 0; k < frames; ++k) {
      if (!runner.context().headless() && const_cast<gl::GlContext&>(runner.context()).should_close()) break;
      const FrameResult f = runner.render_frame(k);
      const bool last = k == frames - 1;
      for (size_t c = 0; c < runner.channels().size(); ++c) {
        auto& ch = runner.channels()[c];
        double readback_ms = 0.0, present_ms = 0.0;
        if (capture_frames.count(k) || last) {
          const auto t0 = Clock::now();
          const auto rgba = ch.target->read_rgba();
          readback_ms = ms_since(t0);
          const int w = ch.target->width(), h = ch.target->height();
          if (capture_frames.count(k)) {
            const std::string name = capture_name(ch, k, f.sim_time_s);
            capture::write_png_rgba((out / name).string(), rgba, w, h);
            captured.push_back(name);
          }
          if (last) {
            const std::string name = c == 0 ? "final.png" : "final_" + ch.spec.name + ".png";
            capture::write_png_rgba((out / name).string(), rgba, w, h);
            captured.push_back(name);
          }
        }
        if (c == 0 && !runner.context().headless()) {
          const auto t0 = Clock::now();
          runner.present();
          present_ms = ms_since(t0);
        }
        log.add_row(frame_log_row(f, ch, readback_ms, present_ms));
      }
      ++rendered;
      if (progress) {
        const double elapsed = ms_since(run_start) / 1000.0;
        std::fprintf(stderr, "\rig run: frame %d/%d  %.1f s elapsed, %.0f ms/frame   ", k + 1, frames, elapsed,
                     elapsed * 1000.0 / (k + 1));
      }
    }
    if (progress) std::fprintf(stderr, "\n");

    const auto& r = s.render;
    nlohmann::json summary = {
        {"scenario", s.name},
        {"scenario_file", args.scenario},
        {"method", r.method},
        {"width", r.width},
        {"height", r.height},
        {"channels", runner.channels().size()},
        {"frames_rendered", rendered},
        {"time_step_s", s.time_step_s},
        {"gl_version", runner.context().gl_version()},
        {"gl_renderer", runner.context().gl_renderer()},
        {"headless", runner.context().headless()},
        {"terrain",
         {{"source", runner.heightfield().source},
          {"width", runner.heightfield().width},
          {"height", runner.heightfield().height},
          {"spacing_x_m", runner.heightfield().spacing_x_m},
          {"spacing_y_m", runner.heightfield().spacing_y_m},
          {"load_ms", runner.load_ms()}}},
        {"frame_time", stats::frame_time_summary(log.frame_ms(), r.frame_budget_ms)},
        {"captures", captured},
    };
    std::ofstream((out / "summary.json").string()) << summary.dump(2) << "\n";
    const bool plotted = plot_frame_times((out / "frames.csv").string(), (out / "frametime.png").string(),
                                          s.name + " / " + r.method + " / " + runner.context().gl_renderer(),
                                          r.frame_budget_ms);
    const auto ft = summary["frame_time"];
    std::printf("ig run: %s, %d frames x %zu channel(s) at %dx%d, method %s on %s: median %.1f ms, p95 %.1f ms\n",
                s.name.c_str(), rendered, runner.channels().size(), r.width, r.height, r.method.c_str(),
                runner.context().gl_renderer().c_str(), ft["median_ms"].get<double>(), ft["p95_ms"].get<double>());
    std::printf("ig run: outputs in %s (frames.csv, summary.json, %zu PNG%s%s)\n", out.string().c_str(),
                captured.size(), captured.size() == 1 ? "" : "s", plotted ? ", frametime.png" : "");
    return plotted ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "ig run: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace ig::app
