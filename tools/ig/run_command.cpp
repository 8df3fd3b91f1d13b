// ig run SCENARIO.json: replay a scenario to the end and leave its outputs
// (frames.csv, summary.json, captured PNGs, final.png, frametime.png).
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli_args.h"
#include "commands.h"
#include "io/recording.h"
#include "session/capture_schedule.h"
#include "session/pose_feed.h"
#include "session/run_outputs.h"
#include "session/scenario_runner.h"

namespace ig::app {
namespace {

constexpr const char* kUsage =
    "usage: ig run SCENARIO.json [--out DIR] [--frames N] [--size WxH] [--method NAME]\n"
    "              [--recording FILE] [--headless | --window [--fullscreen] [--vsync on|off]]\n"
    "              [--shader-dir DIR] [--quiet]\n"
    "Replays a scenario (docs/scenario.md) frame by frame, frame k at sim time k * time.step_s, and\n"
    "writes frames.csv, summary.json, the capture PNGs (capture.times_s, capture.every_s),\n"
    "final.png and frametime.png. Exit status: 0 ok, 1 the run failed, 2 bad arguments.\n";

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
  add_scenario_argument(app, args.scenario, "the scenario file to replay (JSON, docs/scenario.md)");
  app.add_option("--out", args.out_dir, "output folder, created if missing (default out/<scenario name>)")
      ->option_text("DIR");
  add_count_option(app, "--frames", args.run.frames,
                   "render the first N frames only (sim time 0 to (N-1) * time.step_s; default: the scenario's "
                   "whole duration, or the recording's length); capture times after the last rendered frame are "
                   "not saved, and ig run names them in a warning");
  app.add_option("--recording", args.recording,
                 "replay the pose datagrams of an IG recording (ig serve --record, ig send --record) through "
                 "the live decoders and pose filter on a simulated clock, instead of the scenario's path")
      ->option_text("FILE");
  auto* window = add_view_options(app, args.run);
  app.add_flag("--fullscreen", args.run.fullscreen, "a full-screen window (implies --window)")
      ->excludes(app.get_option("--headless"));
  app.add_option("--vsync", vsync, "windowed: wait for the display's refresh, on or off (default: render.vsync, on)")
      ->check(one_of({"on", "off"}))
      ->option_text("on|off");
  add_shader_dir_option(app, args.run.shader_dir);
  app.add_flag("--pass-times", args.run.pass_times,
               "log each pass's own wall time as <pass>_pass_ms in frames.csv: the GL work is finished before and "
               "after every pass, so the frames themselves take longer (a profile, not a benchmark)");
  app.add_flag("--quiet", args.quiet, "no progress line on the terminal (warnings and the summary lines remain)");
  parse_command_line(app, a);
  if (args.scenario.empty()) throw UsageError("missing SCENARIO.json");
  if (vsync) args.run.vsync = *vsync == "on";
  args.run.headless = !(window->count() || args.run.fullscreen);
  return args;
}

// "6, 12 s" (the first few of `times`, and how many more).
std::string list_times(const std::vector<double>& times, std::size_t total) {
  std::string s;
  for (double t : times) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", t);
    s += (s.empty() ? "" : ", ") + std::string(buf);
  }
  s += " s";
  if (total > times.size()) s += " and " + std::to_string(total - times.size()) + " more";
  return s;
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

  // Captures: the frame nearest each scheduled time; the scenario's last
  // frame also serves times after it (within the duration: up to half a step).
  const int scenario_frames = io::scenario_frame_count(s);
  auto capture_time = [&](int k) { return k == scenario_frames - 1 ? std::max(k * s.time_step_s, s.duration_s)
                                                                   : k * s.time_step_s; };
  session::CaptureSchedule captures(s, session::CaptureSchedule::nearest_frame_tolerance(s.time_step_s));
  {
    session::CaptureSchedule reached = captures;  // what the last frame to render leaves unserved
    reached.take(capture_time(frames - 1));
    if (const std::size_t n = reached.pending_count(s.duration_s); n > 0)
      std::cerr << "ig run: warning: " << (args.run.frames ? "--frames " + std::to_string(frames) + " renders"
                                                           : "the recording covers")
                << " frames 0.." << frames - 1 << " (sim time up to " << (frames - 1) * s.time_step_s
                << " s of the scenario's " << s.duration_s << " s): capture time" << (n == 1 ? "" : "s") << " "
                << list_times(reached.pending(s.duration_s, 8), n) << " fall" << (n == 1 ? "s" : "")
                << " after the last rendered frame and " << (n == 1 ? "is" : "are") << " not saved\n";
  }

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
    outputs.frame(runner, f, captures.take(capture_time(k)), k == frames - 1, frames,
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
