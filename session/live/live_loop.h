#pragma once
// The live IG's frame loop (ig serve, docs/live-ig.md): polls the pose
// sources (UDP native / CIGI 3.3 / FlightGear FGNetFDM, unicast or
// multicast, and SocketCAN) without blocking, applies Modbus controls at the
// frame boundary, filters the pose, renders at its own rate (the display's
// in a window, the host's in CIGI synchronous mode), answers host queries
// and CIGI Start Of Frame, saves the scheduled captures and logs every frame
// like ig run. The front end parses the command line; this runs it.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/filter/pose_filter.h"
#include "io/scenario.h"
#include "session/live/serve_plugins.h"
#include "session/run_outputs.h"
#include "session/scenario_runner.h"

namespace ig::session {

struct LiveSettings {
  // Pose sources and replies: ADDR:PORT each (ADDR may be empty: all interfaces).
  std::optional<std::string> udp, cigi, cigi_reply, fgfdm;
  std::optional<std::string> multicast;  // every UDP source binds GROUP:PORT and joins the group
  // The hosts every UDP pose source takes datagrams from (ADDR or ADDR:PORT);
  // empty: each source locks onto its first sender. Others: counted, dropped.
  std::vector<std::string> hosts;
  // Addresses Modbus writes are taken from (reads: anyone); empty: any.
  std::vector<std::string> modbus_writers;
  std::optional<std::string> record;     // write every received datagram here
  std::optional<std::string> modbus;     // Modbus TCP server endpoint
  std::optional<CanSourceSettings> can;  // SocketCAN pose source
  io::LatencyMode latency = io::LatencyMode::Smooth;
  bool host_surface_drawn = false;  // HAT/HOT on the surface as drawn (DrawnSurface)
  std::optional<int> frames;        // stop after N frames
  std::optional<double> seconds;    // stop after S seconds
  double rate_hz = 60.0;            // headless frame rate
  bool quiet = false;
};

// Runs until the frame or time limit, SIGINT / SIGTERM or a closed window;
// writes out/ (frames.csv, summary.json, captures) and returns the exit
// status. `scenario` holds the one channel to render; `config` is its file,
// named in the summary. Throws std::runtime_error for settings that cannot
// run (sync latency without CIGI, an unopenable socket).
int run_live(io::Scenario scenario, const std::string& config, const std::filesystem::path& out,
             const RunOptions& run, const LiveSettings& settings);

}  // namespace ig::session
