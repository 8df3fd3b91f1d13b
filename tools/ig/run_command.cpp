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

#include "cli_args.h"
#include "commands.h"
#include "io/recording.h"
#include "session/pose_feed.h"
#include "session/run_outputs.h"
#include "session/scenario_runner.h"

namespace ig::app {
namespace {

constexpr const char* kUsage =
    "usage: ig run SCENARIO.json [--out DIR] [--frames N] [--size WxH] [--method NAME]\n"
    "              [--recording FILE] [--headless | --window [--fullscreen] [--vsync on|off]]\n"
    "              [--shader-dir DIR] [--quiet]\n";

struct Args {
  std::string scenario;
  std::string out_dir;
  session::RunOptions run;
  std::optional<std::string> recording;  // replay recorded datagrams instead of the path
  bool quiet = false;
};

Args parse_args(const std::vector<std::string>& a) {
  Args args;
  CLI::App app("ig run");
  std::optional<std::string> vsync;
  app.add_option("scenario", args.scenario);
  app.add_option("--out", args.out_dir);
  app.add_option("--frames", args.run.frames)->check(positive_int());
  add_size_option(app, "--size", args.run.width, args.run.height);
  app.add_option("--method", args.run.method);
  app.add_option("--recording", args.recording);
  auto* headless = app.add_flag("--headless");
  auto* window = app.add_flag("--window")->excludes(headless);
  app.add_flag("--fullscreen", args.run.fullscreen)->excludes(headless);
  app.add_option("--vsync", vsync)->check(one_of({"on", "off"}));
  app.add_option("--shader-dir", args.run.shader_dir);
  app.add_flag("--quiet", args.quiet);
  parse_command_line(app, a);
  if (args.scenario.empty()) throw UsageError("missing SCENARIO.json");
  if (vsync) args.run.vsync = *vsync == "on";
  args.run.headless = !(window->count() || args.run.fullscreen);
  return args;
}

// ig run with its parsed arguments: the exit status.
int run(const Args& args) {
  io::Scenario scenario = io::load_scenario(args.scenario);
  namespace fs = std::filesystem;
  const fs::path out = args.out_dir.empty() ? fs::path("out") / scenario.name : fs::path(args.out_dir);
  fs::create_directories(out);

  session::ScenarioRunner runner(std::move(scenario), args.run);
  const auto& s = runner.scenario();

  // A recording replaces the scripted path: its datagrams go through the
  // same decoders and filter as live, on a simulated clock (deterministic).
  std::vector<io::RecordedDatagram> records;
  std::optional<session::PoseFeed> feed;
  double t0 = 0.0;
  int frames = runner.frame_count();
  if (args.recording) {
    records = io::read_recording(*args.recording);
    if (records.empty()) throw std::runtime_error(*args.recording + ": recording holds no datagrams");
    feed.emplace(runner.heightfield());
    t0 = records.front().receive_time_s;
    if (!args.run.frames)
      frames = int((records.back().receive_time_s - t0) / s.time_step_s) + 1;
  }

  // Frames to capture: the nearest frame to each capture time inside the run.
  std::set<int> capture_frames;
  for (double t : s.capture_times_s)
    if (const int k = std::min(int(std::lround(t / s.time_step_s)), io::scenario_frame_count(s) - 1); k < frames)
      capture_frames.insert(k);

  session::RunOutputs outputs(out, "ig run", !args.quiet && isatty(STDERR_FILENO));
  size_t next_record = 0;
  for (int k = 0; k < frames; ++k) {
    if (!runner.context().headless() && runner.window_closed()) break;
    session::FrameResult f;
    if (feed) {
      const double now = t0 + k * s.time_step_s;
      for (; next_record < records.size() && records[next_record].receive_time_s <= now; ++next_record)
        feed->intake().handle(records[next_record].protocol, records[next_record].bytes,
                              records[next_record].receive_time_s);
      f = runner.render_pose(k, k * s.time_step_s, feed->pose_at(now, runner.pose_at(0.0)));
    } else {
      f = runner.render_frame(k);
    }
    outputs.frame(runner, f, capture_frames.count(k) > 0, k == frames - 1, frames,
                  feed ? std::function<void(std::vector<stats::Cell>&)>(
                             [&](std::vector<stats::Cell>& row) { feed->append_columns(row); })
                       : nullptr);
  }
  nlohmann::json extra = nlohmann::json::object();
  if (feed) {
    extra["recording"] = *args.recording;
    extra["pose_intake"] = feed->summary();
  }
  return outputs.finish(runner, args.scenario, extra);
}

}  // namespace

int run_run_command(const std::vector<std::string>& argv) {
  return run_command("ig run", kUsage, parse_args, argv, run);
}

}  // namespace ig::app
