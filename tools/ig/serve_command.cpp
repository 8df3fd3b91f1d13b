// ig serve: the live IG's command line. The loop itself is the session's
// (session/live/live_loop.h).
#include <algorithm>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_args.h"
#include "commands.h"
#include "io/net/sender_filter.h"
#include "io/scenario.h"
#include "session/live/live_loop.h"

namespace ig::app {
namespace {

constexpr const char* kUsage =
    "usage: ig serve [--config FILE] [--udp ADDR:PORT] [--cigi ADDR:PORT [--cigi-reply HOST:PORT]]\n"
    "                [--fgfdm ADDR:PORT] [--multicast GROUP] [--channel NAME] [--headless | --window]\n"
    "                [--out DIR] [--frames N | --seconds S] [--rate HZ] [--record FILE]\n"
    "                [--size WxH] [--method NAME] [--modbus ADDR:PORT] [--latency smooth|latest|sync] [--quiet]\n"
    "                [--host-surface full|drawn] [--host ADDR[:PORT]]... [--modbus-writer ADDR]...\n"
    "                [--can IFNAME [--can-altitude 320|322|332] [--can-node N] [--can-max-age-ms MS]]\n"
    "The live IG (docs/live-ig.md): renders the ownship pose received from a host at its own rate\n"
    "and logs every frame like ig run. At least one pose source (--udp, --cigi, --fgfdm, --can).\n"
    "ADDR may be empty (':5500' = all interfaces). Stops after --frames / --seconds, on SIGINT or\n"
    "SIGTERM, or when the window closes. Exit status: 0 ok, 1 failed, 2 bad arguments.\n";

// ADDR or (with_port) ADDR:PORT, as --host and --modbus-writer take them.
CLI::Validator host_pattern(bool with_port) {
  return CLI::Validator(
      [with_port](std::string& text) -> std::string {
        try {
          if (io::net::parse_host_pattern(text).port && !with_port) return text + ": an address, without a port";
          return "";
        } catch (const std::exception& e) {
          return e.what();
        }
      },
      with_port ? "ADDR[:PORT]" : "ADDR");
}

struct Args {
  std::string config;
  std::optional<std::string> channel;
  std::string out_dir;
  session::RunOptions run;
  session::LiveSettings live;
  std::optional<io::LatencyMode> latency;  // overrides the config's live.latency
  std::optional<std::string> can;
  session::CanSourceSettings can_settings;
};

Args parse_args(const std::vector<std::string>& a) {
  Args args;
  CLI::App app("ig serve");
  std::optional<std::string> host_surface;
  app.add_option("--config", args.config,
                 "scenario file giving the terrain, render settings, channels and capture schedule; its path's "
                 "first key is the pose shown until the first packet (default scenarios/default.json)")
      ->option_text("FILE");
  app.add_option("--udp", args.live.udp, "receive native IGPS pose datagrams on this port (docs/protocol.md); native "
                                    "height and line-of-sight queries are answered to their sender")
      ->option_text("ADDR:PORT");
  auto* cigi = app.add_option("--cigi", args.live.cigi, "receive CIGI 3.3 host datagrams on this port")
                   ->option_text("ADDR:PORT");
  app.add_option("--cigi-reply", args.live.cigi_reply,
                 "send CIGI Start Of Frame there every frame, with the answers to the host's HAT/HOT and "
                 "line-of-sight requests (docs/host-services.md); needs --cigi")
      ->needs(cigi)
      ->option_text("HOST:PORT");
  app.add_option("--fgfdm", args.live.fgfdm, "receive FlightGear FGNetFDM v24 datagrams on this port")
      ->option_text("ADDR:PORT");
  app.add_option("--multicast", args.live.multicast,
                 "every UDP source binds GROUP:PORT and joins the group on loopback, so several channel "
                 "processes share one stream")
      ->option_text("GROUP");
  app.add_option("--host", args.live.hosts,
                 "take pose datagrams only from this host (repeatable; ADDR: any port, ADDR:PORT: that socket); "
                 "without it each source takes them from its first sender. Others are counted "
                 "(foreign_datagrams) and dropped")
      ->check(host_pattern(true))
      ->option_text("ADDR[:PORT]");
  app.add_option("--channel", args.channel,
                 "render this channel of the config (its view offsets and field of view); default: the first")
      ->option_text("NAME");
  app.add_option("--record", args.live.record,
                 "write every received datagram with its receive time to FILE (replay: ig run --recording)")
      ->option_text("FILE");
  app.add_option_function<std::string>("--latency", [&](const std::string& v) { args.latency = io::parse_latency_mode(v); },
                                       "smooth: interpolate behind an adaptive playout delay; latest: the newest pose "
                                       "extrapolated to the frame's display time; sync: CIGI synchronous, one frame "
                                       "per host IG Control (needs --cigi). Default: the config's live.latency, else "
                                       "smooth (docs/pose-filter.md)")
      ->check(one_of({"smooth", "latest", "sync"}))
      ->option_text("MODE");
  app.add_option("--modbus", args.live.modbus, "Modbus TCP status and control server on this port (docs/modbus.md)")
      ->option_text("ADDR:PORT");
  app.add_option("--modbus-writer", args.live.modbus_writers,
                 "take Modbus writes only from this address (repeatable; reads from anyone); others get "
                 "exception 01. Default: writes from any address")
      ->check(host_pattern(false))
      ->option_text("ADDR");
  app.add_option("--host-surface", host_surface,
                 "what HAT/HOT answers are measured on: full (the full-resolution surface, default) or drawn "
                 "(the surface this frame drew: Level0 outside the two-level method's Level1)")
      ->check(one_of({"full", "drawn"}))
      ->option_text("full|drawn");
  app.add_option("--can", args.can,
                 "SocketCAN pose source: CANaerospace parameters and the CAN FD pose frame (docs/can.md); a "
                 "missing or down interface is reported and retried")
      ->option_text("IFNAME");
  app.add_option("--can-altitude", args.can_settings.altitude_id,
                 "CANaerospace identifier the altitude is read from: 320, 322 or 332 (default 322)")
      ->check(can_altitude_id())
      ->option_text("ID");
  app.add_option("--can-node", args.can_settings.node, "take CAN poses from this node only, 0..255 (default: any node)")
      ->check(can_node_id())
      ->option_text("N");
  app.add_option("--can-max-age-ms", args.can_settings.max_age_ms,
                 "CAN pose fields older than this are stale, milliseconds (default 100)")
      ->check(positive_number())
      ->option_text("MS");
  app.add_option("--out", args.out_dir, "output folder (default out/serve_<scenario>_<channel>)")->option_text("DIR");
  auto* frames = app.add_option("--frames", args.live.frames, "stop after N frames (default: run until stopped)")
                     ->check(positive_int())
                     ->option_text("N");
  app.add_option("--seconds", args.live.seconds, "stop after S seconds (default: run until stopped)")
      ->check(positive_number())
      ->excludes(frames)
      ->option_text("S");
  app.add_option("--rate", args.live.rate_hz, "headless frame rate, frames a second (default 60; a window follows vsync)")
      ->check(positive_number())
      ->option_text("HZ");
  auto* window = add_view_options(app, args.run);
  app.add_flag("--quiet", args.live.quiet, "no progress line and no Modbus or CAN status lines");
  parse_command_line(app, a);
  if (!args.live.udp && !args.live.cigi && !args.live.fgfdm && !args.can)
    throw UsageError("no pose source: give --udp, --cigi, --fgfdm or --can");
  args.live.host_surface_drawn = host_surface == "drawn";
  args.run.headless = !window->count();
  if (args.can) {
    args.can_settings.ifname = *args.can;
    args.can_settings.quiet = args.live.quiet;
    args.live.can = args.can_settings;
  }
  try {
    if (args.live.modbus) session::check_modbus_endpoint(*args.live.modbus);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return args;
}

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
  session::LiveSettings live = args.live;
  live.latency = args.latency.value_or(scenario.live_latency);
  return session::run_live(std::move(scenario), config, out, args.run, live);
}


}  // namespace

int run_serve_command(const std::vector<std::string>& argv) {
  return run_command("ig serve", kUsage, parse_args, argv, run);
}

}  // namespace ig::app
