// ig serve: the live IG. Polls its pose sources (UDP native / CIGI 3.3 /
// FlightGear FGNetFDM, unicast or multicast) without blocking, filters the
// pose, renders at its own rate (or the display's in a window), answers CIGI
// hosts with Start Of Frame, and logs every frame like ig run.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_args.h"
#include "commands.h"
#include "session/drawn_surface.h"
#include "host_services.h"
#include "io/host_view_control.h"
#include "io/net/udp_socket.h"
#include "io/recording.h"
#include "io/wire/cigi.h"
#include "session/capture_schedule.h"
#include "session/pose_feed.h"
#include "session/run_outputs.h"
#include "session/scenario_runner.h"
#include "session/scene_setup.h"
#include "serve_plugins.h"

namespace ig::app {
namespace {

constexpr const char* kUsage =
    "usage: ig serve [--config FILE] [--udp ADDR:PORT] [--cigi ADDR:PORT [--cigi-reply HOST:PORT]]\n"
    "                [--fgfdm ADDR:PORT] [--multicast GROUP] [--channel NAME] [--headless | --window]\n"
    "                [--out DIR] [--frames N | --seconds S] [--rate HZ] [--record FILE]\n"
    "                [--size WxH] [--method NAME] [--modbus ADDR:PORT] [--latency smooth|latest|sync] [--quiet]\n"
    "                [--host-surface full|drawn]\n"
    "                [--can IFNAME [--can-altitude 320|322|332] [--can-node N] [--can-max-age-ms MS]]\n"
    "The live IG (docs/live-ig.md): renders the ownship pose received from a host at its own rate\n"
    "and logs every frame like ig run. At least one pose source (--udp, --cigi, --fgfdm, --can).\n"
    "ADDR may be empty (':5500' = all interfaces). Stops after --frames / --seconds, on SIGINT or\n"
    "SIGTERM, or when the window closes. Exit status: 0 ok, 1 failed, 2 bad arguments.\n";

std::atomic<bool> g_stop{false};
extern "C" void on_signal(int) { g_stop = true; }

struct Args {
  std::string config;
  std::optional<std::string> udp, cigi, cigi_reply, fgfdm, multicast, channel, record, modbus, can;
  std::optional<io::LatencyMode> latency;  // overrides the config's live.latency
  bool host_surface_drawn = false;
  int can_altitude = 322;
  std::optional<int> can_node;
  double can_max_age_ms = 100.0;
  std::string out_dir;
  std::optional<int> frames;
  std::optional<double> seconds;
  double rate_hz = 60.0;
  session::RunOptions run;
  bool quiet = false;
};

Args parse_args(const std::vector<std::string>& a) {
  Args args;
  CLI::App app("ig serve");
  std::optional<std::string> host_surface;
  app.add_option("--config", args.config,
                 "scenario file giving the terrain, render settings, channels and capture schedule; its path's "
                 "first key is the pose shown until the first packet (default scenarios/default.json)")
      ->option_text("FILE");
  app.add_option("--udp", args.udp, "receive native IGPS pose datagrams on this port (docs/protocol.md); native "
                                    "height and line-of-sight queries are answered to their sender")
      ->option_text("ADDR:PORT");
  auto* cigi = app.add_option("--cigi", args.cigi, "receive CIGI 3.3 host datagrams on this port")
                   ->option_text("ADDR:PORT");
  app.add_option("--cigi-reply", args.cigi_reply,
                 "send CIGI Start Of Frame there every frame, with the answers to the host's HAT/HOT and "
                 "line-of-sight requests (docs/host-services.md); needs --cigi")
      ->needs(cigi)
      ->option_text("HOST:PORT");
  app.add_option("--fgfdm", args.fgfdm, "receive FlightGear FGNetFDM v24 datagrams on this port")
      ->option_text("ADDR:PORT");
  app.add_option("--multicast", args.multicast,
                 "every UDP source binds GROUP:PORT and joins the group on loopback, so several channel "
                 "processes share one stream")
      ->option_text("GROUP");
  app.add_option("--channel", args.channel,
                 "render this channel of the config (its view offsets and field of view); default: the first")
      ->option_text("NAME");
  app.add_option("--record", args.record,
                 "write every received datagram with its receive time to FILE (replay: ig run --recording)")
      ->option_text("FILE");
  app.add_option_function<std::string>("--latency", [&](const std::string& v) { args.latency = io::parse_latency_mode(v); },
                                       "smooth: interpolate behind an adaptive playout delay; latest: the newest pose "
                                       "extrapolated to the frame's display time; sync: CIGI synchronous, one frame "
                                       "per host IG Control (needs --cigi). Default: the config's live.latency, else "
                                       "smooth (docs/pose-filter.md)")
      ->check(one_of({"smooth", "latest", "sync"}))
      ->option_text("MODE");
  app.add_option("--modbus", args.modbus, "Modbus TCP status and control server on this port (docs/modbus.md)")
      ->option_text("ADDR:PORT");
  app.add_option("--host-surface", host_surface,
                 "what HAT/HOT answers are measured on: full (the full-resolution surface, default) or drawn "
                 "(the surface this frame drew: Level0 outside the two-level method's Level1)")
      ->check(one_of({"full", "drawn"}))
      ->option_text("full|drawn");
  app.add_option("--can", args.can,
                 "SocketCAN pose source: CANaerospace parameters and the CAN FD pose frame (docs/can.md); a "
                 "missing or down interface is reported and retried")
      ->option_text("IFNAME");
  app.add_option("--can-altitude", args.can_altitude,
                 "CANaerospace identifier the altitude is read from: 320, 322 or 332 (default 322)")
      ->check(can_altitude_id())
      ->option_text("ID");
  app.add_option("--can-node", args.can_node, "take CAN poses from this node only, 0..255 (default: any node)")
      ->check(can_node_id())
      ->option_text("N");
  app.add_option("--can-max-age-ms", args.can_max_age_ms,
                 "CAN pose fields older than this are stale, milliseconds (default 100)")
      ->check(positive_number())
      ->option_text("MS");
  app.add_option("--out", args.out_dir, "output folder (default out/serve_<scenario>_<channel>)")->option_text("DIR");
  auto* frames = app.add_option("--frames", args.frames, "stop after N frames (default: run until stopped)")
                     ->check(positive_int())
                     ->option_text("N");
  app.add_option("--seconds", args.seconds, "stop after S seconds (default: run until stopped)")
      ->check(positive_number())
      ->excludes(frames)
      ->option_text("S");
  app.add_option("--rate", args.rate_hz, "headless frame rate, frames a second (default 60; a window follows vsync)")
      ->check(positive_number())
      ->option_text("HZ");
  add_size_option(app, "--size", args.run.width, args.run.height)
      ->description("image size in pixels (default: the config's render.width x render.height)")
      ->option_text("WxH");
  app.add_option("--method", args.run.method, "terrain LOD method (default: the config's render.method, else twolevel)")
      ->option_text("NAME");
  auto* headless = app.add_flag("--headless")->description("render off-screen (the default)");
  auto* window = app.add_flag("--window")->description("show the view in a window (GLFW, needs X)")->excludes(headless);
  app.add_flag("--quiet", args.quiet, "no progress line and no Modbus or CAN status lines");
  parse_command_line(app, a);
  if (!args.udp && !args.cigi && !args.fgfdm && !args.can)
    throw UsageError("no pose source: give --udp, --cigi, --fgfdm or --can");
  args.host_surface_drawn = host_surface == "drawn";
  args.run.headless = !window->count();
  if (args.modbus) check_modbus_endpoint(*args.modbus);
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


// ig serve with its parsed arguments: the exit status.
int run(const Args& args) {
  const std::string config = args.config.empty() ? default_scenario_file() : args.config;
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
  const io::LatencyMode latency = args.latency.value_or(scenario.live_latency);
  if (latency == io::LatencyMode::Synchronous && !args.cigi)
    throw std::runtime_error("latency mode sync is CIGI synchronous operation: it needs --cigi");

  std::vector<Source> sources;
  auto open = [&](const std::optional<std::string>& ep, io::Protocol p) {
    if (ep) sources.push_back({p, std::make_unique<io::net::UdpReceiver>(source_endpoint(*ep, args.multicast))});
  };
  open(args.udp, io::Protocol::Native);
  open(args.cigi, io::Protocol::Cigi);
  open(args.fgfdm, io::Protocol::FgNetFdm);
  Source* cigi_source = nullptr;
  for (auto& src : sources)
    if (src.protocol == io::Protocol::Cigi) cigi_source = &src;
  std::unique_ptr<io::net::UdpSender> cigi_reply;
  if (args.cigi_reply) cigi_reply = std::make_unique<io::net::UdpSender>(*args.cigi_reply);
  std::unique_ptr<io::RecordingWriter> recorder;
  if (args.record) recorder = std::make_unique<io::RecordingWriter>(*args.record);

  session::ScenarioRunner runner(std::move(scenario), args.run);
  session::PoseFeed feed(runner.heightfield());
  feed.set_latency_mode(latency);
  if (!feed.georeferenced())
    std::cerr << "ig serve: the terrain has no georeference: only local-frame poses are placed; geodetic "
                 "packets (CIGI, FlightGear, native geodetic) are counted as rejected\n";
  const io::Pose initial = runner.pose_at(0.0);
  // CIGI View Control / View Definition set the channel as a config would.
  io::HostViewControl views;
  const io::HostViewControl::ChannelLookup channel_spec = [&runner](std::uint16_t view) -> io::ChannelSpec* {
    return view < runner.channels().size() ? &runner.channels()[view].spec : nullptr;
  };
  // Host services answer CIGI hosts on the reply port and native queries
  // to their sender, from the terrain as drawn (sharing the scene's
  // min/max pyramid).
  std::unique_ptr<HostServices> services;
  if (cigi_reply || args.udp)
    services = std::make_unique<HostServices>(runner.heightfield(), runner.scene().earth_radius_m(),
                                              session::geodetic_placer(runner.heightfield()),
                                              session::local_to_geodetic(runner.heightfield()), HostServicesOptions{},
                                              &runner.scene().height_pyramid());
  session::DrawnSurface drawn(runner);
  if (services && args.host_surface_drawn)
    services->set_drawn_height([&drawn](double x, double y) { return drawn.level0_height_at(x, y); });
  std::unique_ptr<ControlSurface> control;  // Modbus
  if (args.modbus) control = make_modbus_surface(*args.modbus, runner, latency, args.quiet);
  std::optional<io::Pose> last_pose;  // for freeze
  std::unique_ptr<ExtraPoseSource> extra_source;  // SocketCAN
  if (args.can)
    extra_source = make_can_source({*args.can, args.can_altitude, args.can_node, args.can_max_age_ms, args.quiet});

  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  session::RunOutputs outputs(out, "ig serve", !args.quiet && isatty(STDERR_FILENO));
  const double period = 1.0 / args.rate_hz;
  const double start = io::net::steady_now_s();
  double next_tick = start;
  const int total = args.frames.value_or(0);
  // capture.times_s and capture.every_s: seconds since the IG started; the
  // first frame at or after each.
  session::CaptureSchedule captures(runner.scenario(), 0.0);
  double display_lead_s = 0.0;  // frame start -> frame complete, smoothed (the latest mode's lead)
  std::uint64_t sync_waits = 0, sync_frames = 0;
  std::optional<std::array<std::uint8_t, io::wire::kCigiStartOfFrameSize>> last_sof;
  auto poll_source = [&](Source& src, std::size_t max_datagrams) {
    return src.socket->poll(
        [&](std::span<const std::uint8_t> d, double t, const sockaddr_in& from) {
          if (services && src.protocol == io::Protocol::Native && io::wire::is_native_query(d)) {
            if (const auto answer = services->answer_native(d)) src.socket->send_to(*answer, from);
            return;
          }
          if (recorder) recorder->write(src.protocol, d, t);
          feed.intake().handle(src.protocol, d, t);
          if (src.protocol == io::Protocol::Cigi) {
            if (services && cigi_reply) services->take(d);  // answered only with somewhere to send them
            views.take(d, channel_spec);
          }
        },
        max_datagrams);
  };
  for (int k = 0;; ++k) {
    // The mode in effect is the filter's (Modbus may change it at a frame boundary).
    const bool sync = feed.filter().latency_mode() == io::LatencyMode::Synchronous && cigi_source;
    if (sync) {
      // CIGI synchronous operation: this frame is the host's next IG
      // Control. Read the CIGI socket one datagram at a time until one
      // carries it; while the host is silent, repeat the last Start Of Frame
      // every 0.25 s so a host that waits for it can (re)start. Before the
      // first frame that is a Start Of Frame for IG frame 0 (CigiMiniHost
      // waits for one before its first datagram).
      const std::uint64_t before = feed.intake().ig_controls();
      auto announce = [&] {
        if (!cigi_reply) return;
        if (!last_sof)
          last_sof = io::wire::encode_cigi_start_of_frame(0, 0, 0, io::wire::kCigiModeOperate, false);
        cigi_reply->send(*last_sof);
      };
      if (k == 0) announce();
      while (feed.intake().ig_controls() == before && !g_stop) {
        if (poll_source(*cigi_source, 1) > 0) continue;
        if (args.seconds && io::net::steady_now_s() - start >= *args.seconds) break;
        if (!cigi_source->socket->wait_readable(0.25)) {
          ++sync_waits;
          announce();
        }
      }
      // No host frame came (stopped, or --seconds ran out): no frame for it.
      if (feed.intake().ig_controls() == before) break;
      ++sync_frames;
    }
    // Poll every source: whatever has arrived, never waiting. The frame
    // starts after, so every receive time is in its past.
    for (auto& src : sources)
      if (!sync || &src != cigi_source) poll_source(src, 4096);
    if (extra_source) extra_source->poll(feed);
    const double frame_start = io::net::steady_now_s();
    const bool last = (args.frames && k == *args.frames - 1) ||
                      (args.seconds && frame_start - start + (sync ? 0.0 : period) >= *args.seconds) || g_stop;
    // Controls take effect here, at the frame boundary, before rendering.
    bool capture = captures.take(frame_start - start), frozen = false;
    if (control) {
      const auto applied = control->apply_controls();
      capture = capture || applied.capture;
      frozen = applied.frozen;
      if (applied.latency) {
        if (*applied.latency == io::LatencyMode::Synchronous && !cigi_source) {
          std::cerr << "ig serve: modbus: latency_mode 2 (CIGI synchronous) needs --cigi; keeping "
                    << io::latency_mode_name(feed.filter().latency_mode()) << "\n";
        } else {
          feed.set_latency_mode(*applied.latency);
          if (!args.quiet)
            std::cerr << "ig serve: modbus: latency mode " << io::latency_mode_name(*applied.latency) << "\n";
        }
      }
    }
    const auto t0 = std::chrono::steady_clock::now();
    // Frozen: the last pose again; the sources are still drained and counted.
    const io::Pose pose = frozen && last_pose ? *last_pose : feed.pose_at(frame_start, initial, display_lead_s);
    last_pose = pose;
    const double pose_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const session::FrameResult f = runner.render_pose(k, frame_start - start, pose, pose_ms);
    const double complete = io::net::steady_now_s();  // the renderer ends with glFinish
    feed.frame_complete(complete);
    display_lead_s += 0.1 * (std::min(complete - frame_start, 2.0 * period) - display_lead_s);
    if (cigi_reply) {
      last_sof = io::wire::encode_cigi_start_of_frame(
          std::uint32_t(k), feed.intake().last_host_frame().value_or(0),
          std::uint32_t(std::llround((frame_start - start) * 1e5)), io::wire::kCigiModeOperate, false);
      cigi_reply->send(services->frame_datagram(*last_sof, pose));  // with this frame's answers
    } else if (services) {
      services->answer_frame(pose);  // the frame ends: a new native budget
    }
    outputs.frame(runner, f, capture, last, total, [&](std::vector<stats::Cell>& row) { feed.append_columns(row); });
    if (control)
      control->publish(k + 1, frame_start, io::net::steady_now_s(), feed, last,
                       extra_source ? extra_source->status() : ExtraSourceStatus{});
    if (last || (!runner.context().headless() && runner.window_closed())) break;
    if (runner.context().headless() && !sync) {
      // Own rate; a window paces on vsync; synchronous mode on the host.
      next_tick += period;
      const double now = io::net::steady_now_s();
      if (next_tick > now) std::this_thread::sleep_for(std::chrono::duration<double>(next_tick - now));
      else next_tick = now;  // overran: do not try to catch up
    } else {
      next_tick = io::net::steady_now_s();
    }
  }
  std::uint64_t kernel_stamped = 0, datagrams = 0;
  for (const auto& src : sources) {
    kernel_stamped += src.socket->stats().kernel_timestamps;
    datagrams += src.socket->stats().datagrams;
  }
  nlohmann::json extra = {{"pose_intake", feed.summary()},
                          {"rate_hz", args.rate_hz},
                          {"latency_mode", io::latency_mode_name(feed.filter().latency_mode())},
                          {"datagrams", datagrams},
                          {"kernel_receive_timestamps", kernel_stamped}};
  if (cigi_source) extra["cigi_sync"] = {{"frames", sync_frames}, {"waits", sync_waits}};
  if (services) extra["host_services"] = services->summary();
  if (cigi_source) extra["view_control"] = views.summary();
  if (recorder) extra["recording"] = {{"file", *args.record}, {"datagrams", recorder->count()}};
  if (extra_source) extra[extra_source->summary_key()] = extra_source->summary();
  if (control) extra["modbus"] = control->summary();
  return outputs.finish(runner, config, extra);
}

}  // namespace

int run_serve_command(const std::vector<std::string>& argv) {
  return run_command("ig serve", kUsage, parse_args, argv, run);
}

}  // namespace ig::app
