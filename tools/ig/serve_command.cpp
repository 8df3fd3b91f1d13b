// ig serve: the live IG. Polls its pose sources (UDP native / CIGI 3.3 /
// FlightGear FGNetFDM, unicast or multicast) without blocking, filters the
// pose, renders at its own rate (or the display's in a window), answers CIGI
// hosts with Start Of Frame, and logs every frame like ig run.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli_args.h"
#include "commands.h"
#include "io/net/udp_socket.h"
#include "io/recording.h"
#include "io/wire/cigi.h"
#include "pose_feed.h"
#include "run_outputs.h"
#include "scenario_runner.h"

namespace ig::app {
namespace {

constexpr const char* kUsage =
    "usage: ig serve [--config FILE] [--udp ADDR:PORT] [--cigi ADDR:PORT [--cigi-reply HOST:PORT]]\n"
    "                [--fgfdm ADDR:PORT] [--multicast GROUP] [--channel NAME] [--headless | --window]\n"
    "                [--out DIR] [--frames N | --seconds S] [--rate HZ] [--record FILE]\n"
    "                [--size WxH] [--method NAME] [--quiet]\n"
    "  ADDR may be empty (':5500' = all interfaces); with --multicast GROUP every\n"
    "  source binds GROUP:PORT and joins the group on loopback.\n";

std::atomic<bool> g_stop{false};
extern "C" void on_signal(int) { g_stop = true; }

struct Args {
  std::string config;
  std::optional<std::string> udp, cigi, cigi_reply, fgfdm, multicast, channel, record;
  std::string out_dir;
  std::optional<int> frames;
  std::optional<double> seconds;
  double rate_hz = 60.0;
  RunOptions run;
  bool quiet = false;
};

Args parse_args(const std::vector<std::string>& a) {
  Args args;
  ArgReader r(a);
  bool window = false, headless = false;
  while (!r.done()) {
    const std::string f = r.next();
    if (f == "--config") args.config = r.value(f);
    else if (f == "--udp") args.udp = r.value(f);
    else if (f == "--cigi") args.cigi = r.value(f);
    else if (f == "--cigi-reply") args.cigi_reply = r.value(f);
    else if (f == "--fgfdm") args.fgfdm = r.value(f);
    else if (f == "--multicast") args.multicast = r.value(f);
    else if (f == "--channel") args.channel = r.value(f);
    else if (f == "--record") args.record = r.value(f);
    else if (f == "--out") args.out_dir = r.value(f);
    else if (f == "--frames") args.frames = r.positive_int(f);
    else if (f == "--seconds") args.seconds = r.positive_double(f);
    else if (f == "--rate") args.rate_hz = r.positive_double(f);
    else if (f == "--size") {
      int w = 0, h = 0;
      r.size(f, w, h);
      args.run.width = w;
      args.run.height = h;
    } else if (f == "--method") args.run.method = r.value(f);
    else if (f == "--headless") headless = true;
    else if (f == "--window") window = true;
    else if (f == "--quiet") args.quiet = true;
    else throw UsageError("unknown option " + f);
  }
  if (window && headless) throw UsageError("--window and --headless exclude each other");
  if (args.frames && args.seconds) throw UsageError("--frames and --seconds exclude each other");
  if (args.cigi_reply && !args.cigi) throw UsageError("--cigi-reply needs --cigi");
  if (!args.udp && !args.cigi && !args.fgfdm) throw UsageError("no pose source: give --udp, --cigi or --fgfdm");
  args.run.headless = !window;
  return args;
}

// With --multicast GROUP a source's address becomes GROUP (its port kept).
std::string source_endpoint(const std::string& endpoint, const std::optional<std::string>& group) {
  if (!group) return endpoint.front() == ':' ? "0.0.0.0" + endpoint : endpoint;
  return *group + endpoint.substr(endpoint.rfind(':'));
}

struct Source {
  io::Protocol protocol;
  std::unique_ptr<io::net::UdpReceiver> socket;
};

}  // namespace

int run_serve_command(const std::vector<std::string>& argv) {
  Args args;
  try {
    args = parse_args(argv);
  } catch (const UsageError& e) {
    std::cerr << "ig serve: " << e.what() << "\n" << kUsage;
    return 2;
  }
  try {
    const std::string config = args.config.empty() ? std::string(IG_SOURCE_DIR) + "/scenarios/default.json" : args.config;
    io::Scenario scenario = io::load_scenario(config);
    if (args.channel) {  // one process = one channel of the config
      auto it = std::find_if(scenario.channels.begin(), scenario.channels.end(),
                             [&](const io::ChannelSpec& c) { return c.name == *args.channel; });
      if (it == scenario.channels.end()) throw std::runtime_error(config + ": no channel named '" + *args.channel + "'");
      scenario.channels = {*it};
    } else {
      scenario.channels.resize(1);
    }
    const std::string name = scenario.name + "_" + scenario.channels.front().name;
    const std::filesystem::path out = args.out_dir.empty() ? std::filesystem::path("out") / ("serve_" + name)
                                                           : std::filesystem::path(args.out_dir);

    std::vector<Source> sources;
    auto open = [&](const std::optional<std::string>& ep, io::Protocol p) {
      if (ep) sources.push_back({p, std::make_unique<io::net::UdpReceiver>(source_endpoint(*ep, args.multicast))});
    };
    open(args.udp, io::Protocol::Native);
    open(args.cigi, io::Protocol::Cigi);
    open(args.fgfdm, io::Protocol::FgNetFdm);
    std::unique_ptr<io::net::UdpSender> cigi_reply;
    if (args.cigi_reply) cigi_reply = std::make_unique<io::net::UdpSender>(*args.cigi_reply);
    std::unique_ptr<io::RecordingWriter> recorder;
    if (args.record) recorder = std::make_unique<io::RecordingWriter>(*args.record);

    ScenarioRunner runner(std::move(scenario), args.run);
    PoseFeed feed(runner.heightfield());
    if (!feed.georeferenced())
      std::cerr << "ig serve: the terrain has no georeference: only local-frame poses are placed; geodetic "
                   "packets (CIGI, FlightGear, native geodetic) are counted as rejected\n";
    const io::Pose initial = runner.pose_at(0.0);

    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    RunOutputs outputs(out, "ig serve", !args.quiet && isatty(STDERR_FILENO));
    const double period = 1.0 / args.rate_hz;
    const double start = io::net::steady_now_s();
    double next_tick = start;
    const int total = args.frames.value_or(0);
    for (int k = 0;; ++k) {
      // Poll every source: whatever has arrived, never waiting. The frame
      // starts after, so every receive time is in its past.
      for (auto& src : sources)
        src.socket->poll([&](std::span<const std::uint8_t> d, double t, const sockaddr_in&) {
          if (recorder) recorder->write(src.protocol, d, t);
          feed.intake().handle(src.protocol, d, t);
        });
      const double frame_start = io::net::steady_now_s();
      const bool last = (args.frames && k == *args.frames - 1) ||
                        (args.seconds && frame_start - start + period >= *args.seconds) || g_stop;
      const auto t0 = std::chrono::steady_clock::now();
      const io::Pose pose = feed.pose_at(frame_start, initial);
      const double pose_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      const FrameResult f = runner.render_pose(k, frame_start - start, pose, pose_ms);
      if (cigi_reply) {
        const auto sof = io::wire::encode_cigi_start_of_frame(
            std::uint32_t(k), feed.intake().last_host_frame().value_or(0),
            std::uint32_t(std::llround((frame_start - start) * 1e5)), io::wire::kCigiModeOperate, false);
        cigi_reply->send(sof);
      }
      outputs.frame(runner, f, false, last, total, [&](std::vector<stats::Cell>& row) { feed.append_columns(row); });
      if (last || (!runner.context().headless() && runner.window_closed())) break;
      if (runner.context().headless()) {  // own rate; a window paces on vsync
        next_tick += period;
        const double now = io::net::steady_now_s();
        if (next_tick > now) std::this_thread::sleep_for(std::chrono::duration<double>(next_tick - now));
        else next_tick = now;  // overran: do not try to catch up
      }
    }
    nlohmann::json extra = {{"pose_intake", feed.summary()}, {"rate_hz", args.rate_hz}};
    if (recorder) extra["recording"] = {{"file", *args.record}, {"datagrams", recorder->count()}};
    return outputs.finish(runner, config, extra);
  } catch (const std::exception& e) {
    std::cerr << "ig serve: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace ig::app
