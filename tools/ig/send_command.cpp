// ig send (also build/bin/ig-send): plays a scenario's path as pose packets
// (native, CIGI 3.3 or FlightGear FGNetFDM) to a unicast or multicast
// address at a given rate, with optional loss, jitter, reordering, duplicates
// and corrupted bytes: the host side of the loopback tests and a stand-in for
// a simulation host.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <queue>
#include <thread>

#include "cli_args.h"
#include "commands.h"
#include "io/net/udp_socket.h"
#ifdef IG_WITH_CAN
#include "io/can/can_socket.h"
#endif
#include "io/wire/can_fd_pose.h"
#include "io/wire/canaerospace.h"
#include "io/path_interpolator.h"
#include "io/pose_intake.h"
#include "io/recording.h"
#include "io/wire/cigi.h"
#include "io/pose_stream.h"
#include "session/scene_setup.h"

namespace ig::app {
namespace {

constexpr const char* kUsage =
    "usage: ig send SCENARIO.json --to ADDR:PORT [--protocol native|cigi|fgfdm] [--from ADDR:PORT] [--rate HZ]\n"
    "               [--duration S] [--geodetic] [--loss P] [--burst-loss P --burst-length N]\n"
    "               [--jitter-ms J] [--reorder P] [--duplicate P] [--corrupt P] [--seed N]\n"
    "               [--flood N] [--cigi-listen ADDR:PORT [--cigi-sync]] [--log FILE] [--quiet]\n"
    "               [--no-timestamp] [--pairs N] [--stall-every N [--stall-ms A,B]]\n"
    "       ig send SCENARIO.json --record FILE [--protocol ...] [options as above but --flood]\n"
    "       ig send SCENARIO.json --can IFNAME [--can-fd] [--can-node N] [--can-altitude 320|322|332]\n"
    "               [--can-float-position] [--rate HZ] [--duration S] [impairments as above]\n"
    "Plays a scenario's path (placed on its terrain) as pose packets in real time: the host side of\n"
    "ig serve (docs/live-ig.md). Impairments are seeded and reproducible. Also build/bin/ig-send.\n";

struct Args {
  std::string scenario, to;
  io::Protocol protocol = io::Protocol::Native;
  double rate_hz = 60.0;
  std::optional<double> duration_s;
  bool geodetic = false;
  double loss = 0, burst_loss = 0, jitter_ms = 0, reorder = 0, duplicate = 0, corrupt = 0;
  int burst_length = 10;
  unsigned seed = 1;
  std::optional<int> flood;
  std::optional<std::string> cigi_listen, log, can, record, from;
  bool can_fd = false, can_float_position = false;
  bool no_timestamp = false, cigi_sync = false;
  int pairs = 0, stall_every = 0;
  double stall_a_ms = 133.0, stall_b_ms = 17.0;
  int can_node = 1, can_altitude = 322;
  bool quiet = false;
};

Args parse_args(const std::vector<std::string>& a) {
  Args args;
  CLI::App app("ig send");
  std::string protocol = "native";
  std::optional<std::string> stall_ms;
  add_scenario_argument(app, args.scenario, "the scenario whose path is sent (docs/scenario.md)");
  auto* to = app.add_option("--to", args.to, "where to send the pose datagrams (unicast or multicast)")
                 ->option_text("ADDR:PORT");
  app.add_option("--from", args.from, "send from this local ADDR:PORT (an IG told --host ADDR:PORT takes only it)")
      ->option_text("ADDR:PORT");
  app.add_option("--protocol", protocol,
                 "native (IGPS), cigi (CIGI 3.3) or fgfdm (FlightGear FGNetFDM v24); cigi and fgfdm need a "
                 "terrain with a geographic georeference (default native)")
      ->check(one_of({"native", "cigi", "fgfdm"}))
      ->option_text("NAME");
  app.add_option("--rate", args.rate_hz, "poses a second (default 60)")->check(positive_number())->option_text("HZ");
  app.add_option("--duration", args.duration_s, "seconds of the path to send (default: the scenario's duration)")
      ->check(positive_number())
      ->option_text("S");
  app.add_flag("--geodetic", args.geodetic, "native: send latitude, longitude and altitude instead of local metres");
  // The impairments drawn per packet, each with its probability (default 0).
  const auto add_probability = [&app](const std::string& name, double& p, const std::string& event) {
    app.add_option(name, p, "probability that " + event + " (default 0)")->check(probability())->option_text("P");
  };
  add_probability("--loss", args.loss, "a packet is dropped");
  add_probability("--burst-loss", args.burst_loss, "a burst of --burst-length packets is dropped");
  add_count_option(app, "--burst-length", args.burst_length, "packets a loss burst drops (default 10)");
  app.add_option("--jitter-ms", args.jitter_ms, "each send time delayed by up to J ms, uniformly (default 0)")
      ->check(positive_number())
      ->option_text("J");
  add_probability("--reorder", args.reorder, "a packet is overtaken by the next");
  add_probability("--duplicate", args.duplicate, "a packet is sent twice");
  add_probability("--corrupt", args.corrupt, "a packet has a byte changed");
  add_count_option(app, "--seed", args.seed, "seed of the impairments' random draws (default 1)");
  add_count_option(app, "--flood", args.flood,
                   "send N packets as fast as the socket takes them (no pacing), each the path at the moment it is "
                   "sent");
  auto* cigi_listen = app.add_option("--cigi-listen", args.cigi_listen,
                                     "collect the IG's CIGI Start Of Frame replies there and report their count and "
                                     "whether the frame counter always increased")
                          ->option_text("ADDR:PORT");
  app.add_flag("--cigi-sync", args.cigi_sync,
               "a synchronous CIGI host: wait for the IG's Start Of Frame echoing each host frame before sending "
               "the next (needs --cigi-listen and --protocol cigi)")
      ->needs(cigi_listen);
  app.add_flag("--no-timestamp", args.no_timestamp,
               "no sender time (CIGI: timestamp-valid bit clear, as CigiMiniHost; native: no sender-time field); "
               "FGNetFDM never has one");
  add_count_option(app, "--pairs", args.pairs,
                   "every Nth packet is held up and sent back to back with the next (N >= 2)");
  add_count_option(app, "--stall-every", args.stall_every,
                   "every N packets the host's own frame stalls, as FlightGear's main loop does: gaps of A then B "
                   "ms (--stall-ms), each pose taken when it is sent");
  app.add_option("--stall-ms", stall_ms, "the two stall gaps of --stall-every, milliseconds (default 133,17)")
      ->option_text("A,B");
  app.add_option("--log", args.log,
                 "write every pose sent as CSV (with the sender's steady-clock time), continued 0.5 s past the "
                 "last packet")
      ->option_text("FILE");
  auto* record = app.add_option("--record", args.record,
                                "write the datagrams to an IG recording instead of sending them (no socket, no "
                                "pacing); ig run --recording FILE replays them")
                     ->excludes(to)
                     ->excludes(cigi_listen)
                     ->option_text("FILE");
  app.add_flag("--quiet", args.quiet, "no report lines at the end");
  auto* can = app.add_option("--can", args.can,
                             "send each pose on this SocketCAN interface as CANaerospace frames (geodetic "
                             "position) instead of UDP (docs/can.md); impairments act per pose")
                  ->excludes(to)
                  ->excludes(record)
                  ->option_text("IFNAME");
  app.add_flag("--can-fd", args.can_fd, "send each pose as one 64-byte CAN FD pose frame instead")->needs(can);
  app.add_flag("--can-float-position", args.can_float_position,
               "CANaerospace latitude and longitude as 32-bit floats (default: doubles)")
      ->needs(can);
  app.add_option("--can-node", args.can_node, "the sending node's id, 0..255 (default 1)")
      ->check(can_node_id())
      ->option_text("N");
  app.add_option("--can-altitude", args.can_altitude,
                 "CANaerospace identifier the altitude is sent with: 320, 322 or 332 (default 322)")
      ->check(can_altitude_id())
      ->option_text("ID");
  parse_command_line(app, a);
  if (args.scenario.empty()) throw UsageError("missing SCENARIO.json");
  args.protocol = protocol == "cigi" ? io::Protocol::Cigi : protocol == "fgfdm" ? io::Protocol::FgNetFdm
                                                                                : io::Protocol::Native;
  if (stall_ms) {
    const auto comma = stall_ms->find(',');
    if (comma == std::string::npos) throw UsageError("--stall-ms: expected A,B (milliseconds)");
    args.stall_a_ms = parse_double("--stall-ms", stall_ms->substr(0, comma));
    args.stall_b_ms = parse_double("--stall-ms", stall_ms->substr(comma + 1));
    if (!(args.stall_a_ms > 0 && args.stall_b_ms > 0)) throw UsageError("--stall-ms: both gaps must be > 0");
  }
  if (args.cigi_sync && args.protocol != io::Protocol::Cigi) throw UsageError("--cigi-sync needs --protocol cigi");
  if (args.pairs == 1) throw UsageError("--pairs: N must be at least 2");
  if (args.record && args.flood) throw UsageError("--record: not with --flood (a flood has no schedule)");
  if (args.to.empty() && !args.can && !args.record) throw UsageError("missing --to ADDR:PORT (or --can IFNAME)");
#ifndef IG_WITH_CAN
  if (args.can) throw UsageError("--can: this ig was built without SocketCAN (IG_WITH_CAN=OFF)");
#endif
  return args;
}

struct Packet {
  double send_at_s;
  std::uint32_t order;  // tie-break keeps equal times in sequence
  std::vector<std::uint8_t> bytes;        // UDP: one datagram
  std::vector<io::wire::CanFrame> frames; // CAN: the pose's frames
  std::uint32_t sequence = 0;             // host frame / packet number
  bool operator<(const Packet& o) const { return send_at_s != o.send_at_s ? send_at_s > o.send_at_s : order > o.order; }
};

// ig send with its parsed arguments: the exit status.
int run(const Args& args) {
  const io::Scenario scenario = io::load_scenario(args.scenario);
  const terrain::Heightfield hf = session::load_terrain(scenario.terrain);
  const io::PathInterpolator path(session::place_path(scenario.path, hf));
  const auto to_geodetic = session::local_to_geodetic(hf);
  // CANaerospace carries latitude / longitude only; the FD pose is like native.
  const bool canaerospace = args.can && !args.can_fd;
  const std::string format = args.can ? (args.can_fd ? "canfd" : "canaerospace") : io::protocol_name(args.protocol);
  const bool geodetic = args.geodetic || canaerospace || (!args.can && args.protocol != io::Protocol::Native);
  if (geodetic && !to_geodetic)
    throw std::runtime_error(args.scenario + ": " + format +
                             " needs geodetic positions but the terrain has no geographic georeference "
                             "(give terrain.generator.origin or use --protocol native)");
  std::unique_ptr<io::net::UdpSender> sender;
  std::unique_ptr<io::RecordingWriter> recording;
  if (args.record) recording = std::make_unique<io::RecordingWriter>(*args.record);
  else if (!args.can) sender = std::make_unique<io::net::UdpSender>(args.to, "127.0.0.1", args.from);
#ifdef IG_WITH_CAN
  // A CAN interface that goes down or away mid-stream is reopened every
  // 0.1 s; the poses meanwhile are counted as refused.
  std::unique_ptr<io::can::CanSocket> can;
  if (args.can) {
    can = std::make_unique<io::can::CanSocket>(*args.can, 0.1);
    if (!can->ensure_open(io::net::steady_now_s())) throw std::runtime_error("CAN " + can->last_error());
  }
  io::wire::CanAerospaceEncoder canas_encoder([&] {
    io::wire::CanAerospaceEncodeConfig c;
    c.node_id = std::uint8_t(args.can_node);
    c.altitude_id = std::uint16_t(args.can_altitude);
    c.position_as_double = !args.can_float_position;
    return c;
  }());
#endif
  std::unique_ptr<io::net::UdpReceiver> sof_socket;
  if (args.cigi_listen) sof_socket = std::make_unique<io::net::UdpReceiver>(*args.cigi_listen);
  std::ofstream log;
  if (args.log) {
    log.open(*args.log);
    if (!log) throw std::runtime_error(*args.log + ": cannot create send log");
    log << "sequence,t_s,sender_time_s,sent,x_m,y_m,z_m,heading_deg,pitch_deg,roll_deg,steady_s\n";
  }

  const double duration = args.duration_s.value_or(scenario.duration_s);
  const int count = args.flood ? *args.flood : int(std::floor(duration * args.rate_hz + 1e-9)) + 1;
  const double period = 1.0 / args.rate_hz;
  // A moment to open the receiver's socket; a recording starts at 0 (the
  // same bytes every time).
  const double start = recording ? 0.0 : io::net::steady_now_s() + 0.05;

  // One datagram (or the CAN frames) for sequence i: the path at time t,
  // stamped with the sender's clock (the steady clock) at sender_time.
  auto make_packet = [&](int i, double t, double sender_time, io::Hpr& hpr, io::Pose& pose) {
    io::wire::PoseMessage m = io::path_pose_message(path, t, 0.5 * period, std::uint32_t(i), pose, hpr);
    m.sender_time_s = sender_time;
    m.has_sender_time = !args.no_timestamp;
    if (geodetic) {
      m.frame = io::wire::PoseMessage::Frame::Geodetic;
      m.position = *to_geodetic(pose.position);
    }
    Packet p{0.0, 0, {}, {}, std::uint32_t(i)};
#ifdef IG_WITH_CAN
    if (args.can) {
      if (args.can_fd) p.frames.push_back(io::wire::encode_can_fd_pose(m));
      else canas_encoder.encode(m, p.frames);
      return p;
    }
#endif
    p.bytes = io::encode_pose_datagram(args.protocol, m, std::uint32_t(i));
    return p;
  };

  io::StreamRng rng(args.seed);
  std::uint64_t lost = 0, duplicated = 0, corrupted = 0, reordered = 0;
  auto corrupt = [&](Packet& p) {
    if (!rng.chance(args.corrupt)) return;
    const int flips = 1 + int(rng.uniform() * 3);
    for (int k = 0; k < flips; ++k) {
      if (!p.frames.empty()) {  // a byte of one of the pose's frames
        auto& f = p.frames[size_t(rng.uniform() * p.frames.size())];
        if (f.len > 0) f.data[size_t(rng.uniform() * f.len)] ^= std::uint8_t(1 + rng.gen() % 255);
      } else {
        p.bytes[size_t(rng.uniform() * p.bytes.size())] ^= std::uint8_t(1 + rng.gen() % 255);
      }
    }
    ++corrupted;
  };
  auto log_pose = [&](int i, double t, double sender_time, bool sent, const io::Pose& pose, const io::Hpr& hpr) {
    if (log.is_open())
      log << i << "," << t << "," << sender_time - start << "," << sent << "," << pose.position.x << ","
          << pose.position.y << "," << pose.position.z << "," << hpr.heading_deg << "," << hpr.pitch_deg << ","
          << hpr.roll_deg << "," << std::setprecision(15) << start + t << std::setprecision(6) << "\n";
  };

  // Paced: the whole schedule first (impairments decide send times), then
  // send in time order. Flood: as fast as the socket takes them, each
  // packet the path at the moment it is sent.
  std::priority_queue<Packet> queue;
  if (!args.flood) {
    int burst_left = 0;
    std::uint32_t order = 0;
    double stalled_t = 0.0;  // --stall-every: the host's own (irregular) send clock
    double last_t = 0.0;
    for (int i = 0; i < count; ++i) {
      io::Hpr hpr;
      io::Pose pose;
      double t = i * period;
      if (args.stall_every) {
        t = stalled_t;
        const int phase = i % args.stall_every;
        stalled_t += phase == args.stall_every - 2 ? args.stall_a_ms * 1e-3
                     : phase == args.stall_every - 1 ? args.stall_b_ms * 1e-3
                                                      : period;
      }
      last_t = t;
      Packet pk = make_packet(i, t, start + t, hpr, pose);
      bool sent = true;
      if (burst_left > 0) --burst_left, sent = false;
      else if (rng.chance(args.burst_loss)) burst_left = args.burst_length - 1, sent = false;
      else if (rng.chance(args.loss)) sent = false;
      log_pose(i, t, start + t, sent, pose, hpr);
      if (!sent) {
        ++lost;
        continue;
      }
      corrupt(pk);
      double at = t + rng.uniform() * args.jitter_ms * 1e-3;
      // Held up, then sent just before the next one (same send time, earlier order).
      if (args.pairs && i % args.pairs == args.pairs - 1) at = std::max(at, t + period);
      if (rng.chance(args.reorder)) at += 1.5 * period, ++reordered;  // overtaken by the next packet
      pk.send_at_s = at;
      pk.order = order++;
      queue.push(pk);
      if (rng.chance(args.duplicate)) {
        pk.send_at_s = at + 0.25 * period;
        pk.order = order++;
        queue.push(pk);
        ++duplicated;
      }
    }
    // The log goes on 0.5 s past the last packet (sent = 0): where the host
    // would have been, to judge the IG's extrapolation after the stream stops.
    const double end = last_t;
    for (int j = 1; j * period <= 0.5 + 1e-9; ++j) {
      io::Hpr hpr;
      io::Pose pose;
      make_packet(count - 1 + j, end + j * period, start + end + j * period, hpr, pose);
      log_pose(count - 1 + j, end + j * period, start + end + j * period, false, pose, hpr);
    }
  }

  std::uint64_t sent_ok = 0, send_failed = 0, sof_count = 0, sof_not_increasing = 0;
  // UDP: one datagram; CAN: every frame of the pose (counted per frame).
  auto send_packet = [&](const Packet& p) {
#ifdef IG_WITH_CAN
    if (can) {
      for (const auto& f : p.frames) (can->send(f) ? sent_ok : send_failed)++;
      return;
    }
#endif
    (sender->send(p.bytes) ? sent_ok : send_failed)++;
  };
  std::optional<io::wire::CigiStartOfFrame> last_sof;
  auto poll_sof = [&] {
    if (!sof_socket) return;
    sof_socket->poll([&](std::span<const std::uint8_t> d, double, const sockaddr_in&) {
      const auto r = io::wire::decode_cigi_start_of_frame(d);
      if (!r.sof) return;
      if (last_sof && r.sof->ig_frame <= last_sof->ig_frame) ++sof_not_increasing;
      ++sof_count;
      last_sof = r.sof;
    });
  };
  if (args.flood) {
    double next_log = 0.0;
    for (int i = 0; i < count; ++i) {
      const double now = io::net::steady_now_s();
      const double t = std::clamp(now - start, 0.0, duration);
      io::Hpr hpr;
      io::Pose pose;
      Packet pk = make_packet(i, t, now, hpr, pose);
      if (t >= next_log) log_pose(i, t, now, true, pose, hpr), next_log = t + 0.5 * period;
      corrupt(pk);
      send_packet(pk);
      if (i % 256 == 0) poll_sof();
    }
  }
  std::uint64_t sync_timeouts = 0;
  while (!queue.empty()) {
    const Packet p = queue.top();
    queue.pop();
    if (recording) {  // received when sent: what a loopback without delays delivers
      recording->write(args.protocol, p.bytes, start + p.send_at_s);
      ++sent_ok;
      continue;
    }
    const double wait = start + p.send_at_s - io::net::steady_now_s();
    if (wait > 0) std::this_thread::sleep_for(std::chrono::duration<double>(wait));
    send_packet(p);
    if (args.cigi_sync) {
      // Synchronous host: the next host frame only after the IG's Start Of
      // Frame for this one (2 s without it: counted, go on).
      const double give_up = io::net::steady_now_s() + 2.0;
      while (!last_sof || last_sof->last_host_frame != p.sequence) {
        const double left = give_up - io::net::steady_now_s();
        if (left <= 0) {
          ++sync_timeouts;
          break;
        }
        if (sof_socket->wait_readable(left)) poll_sof();
      }
      continue;
    }
    poll_sof();
  }
  if (sof_socket) {  // the IG answers each frame: collect the last replies
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    poll_sof();
  }
  if (!args.quiet) {
    std::printf("ig send: %d poses as %s to %s: %llu %s sent (%llu refused), %llu lost, %llu duplicated, "
                "%llu reordered, %llu corrupted\n",
                count, format.c_str(), args.can ? args.can->c_str() : args.record ? args.record->c_str() : args.to.c_str(),
                (unsigned long long)sent_ok,
                args.can ? "frames" : "datagrams",
                (unsigned long long)send_failed, (unsigned long long)lost, (unsigned long long)duplicated,
                (unsigned long long)reordered, (unsigned long long)corrupted);
    if (sof_socket)
      std::printf("ig send: %llu CIGI Start Of Frame received, last IG frame %u, last host frame echoed %u, "
                  "%llu not increasing\n",
                  (unsigned long long)sof_count, last_sof ? last_sof->ig_frame : 0u,
                  last_sof ? last_sof->last_host_frame : 0u, (unsigned long long)sof_not_increasing);
    if (args.cigi_sync)
      std::printf("ig send: synchronous: %llu host frames answered, %llu timed out\n",
                  (unsigned long long)(count - lost - sync_timeouts), (unsigned long long)sync_timeouts);
  }
  return 0;
}

}  // namespace

int run_send_command(const std::vector<std::string>& argv) {
  return run_command("ig send", kUsage, parse_args, argv, run);
}

}  // namespace ig::app
