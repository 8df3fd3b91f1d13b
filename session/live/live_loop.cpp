// The live loop (live_loop.h): sources, pacing, CIGI synchronous
// operation, the display lead, controls, captures, replies and the log.
#include "session/live/live_loop.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <iostream>
#include <memory>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/entities/entity_table.h"
#include "io/host_view_control.h"
#include "io/net/sender_filter.h"
#include "io/net/udp_socket.h"
#include "io/wire/cigi_host_datagram.h"
#include "io/recording.h"
#include "io/utc_time.h"
#include "io/wire/cigi.h"
#include "session/capture_schedule.h"
#include "session/drawn_surface.h"
#include "session/heap_trim.h"
#include "session/host_environment.h"
#include "session/host_services.h"
#include "session/pose_feed.h"
#include "session/scene_setup.h"

namespace ig::session {
namespace {

std::atomic<bool> g_stop{false};
extern "C" void on_signal(int) { g_stop = true; }

// With --multicast GROUP a source's address becomes GROUP (its port kept).
std::string source_endpoint(const std::string& endpoint, const std::optional<std::string>& group) {
  if (!group) return endpoint.front() == ':' ? "0.0.0.0" + endpoint : endpoint;
  return *group + endpoint.substr(endpoint.rfind(':'));
}

// The host's time of day, visibility and clouds, from the frame about to render.
void apply_host_environment(HostEnvironment& environment, ScenarioRunner& runner, double sim_time_s,
                            const io::Pose& pose) {
  const auto c =
      environment.changes(pose.position.z, [&runner] { return runner.clock_start().value_or(io::utc_now()); });
  if (c.time_utc && !runner.set_time_of_day(*c.time_utc, sim_time_s, c.clock_runs))
    environment.message("Celestial Sphere Control: the terrain has no georeference to place the sun");
  if (c.visibility_m) runner.scene().set_fog_visibility(*c.visibility_m);
  if (c.clouds)
    for (const auto& why : runner.scene().set_clouds(*c.clouds)) environment.refuse("weather-cloud-layer", why);
}

// Each view's eye (index = channel = CIGI view id), for Position Responses.
std::vector<io::Pose> view_poses(ScenarioRunner& runner) {
  std::vector<io::Pose> out;
  for (const auto& ch : runner.channels()) out.push_back({ch.camera.position, ch.camera.attitude});
  return out;
}

struct Source {
  io::Protocol protocol;
  std::unique_ptr<io::net::UdpReceiver> socket;
  io::net::SenderFilter senders;
};

}  // namespace

int run_live(io::Scenario scenario, const std::string& config, const std::filesystem::path& out,
             const RunOptions& run, const LiveSettings& s) {
  if (s.latency == io::LatencyMode::Synchronous && !s.cigi)
    throw std::runtime_error("latency mode sync is CIGI synchronous operation: it needs --cigi");
  std::vector<Source> sources;
  std::vector<io::net::HostPattern> hosts;
  for (const auto& h : s.hosts) hosts.push_back(io::net::parse_host_pattern(h));
  auto open = [&](const std::optional<std::string>& ep, io::Protocol p) {
    if (ep)
      sources.push_back(
          {p, std::make_unique<io::net::UdpReceiver>(source_endpoint(*ep, s.multicast)), io::net::SenderFilter(hosts)});
  };
  open(s.udp, io::Protocol::Native);
  open(s.cigi, io::Protocol::Cigi);
  open(s.fgfdm, io::Protocol::FgNetFdm);
  Source* cigi_source = nullptr;
  for (auto& src : sources)
    if (src.protocol == io::Protocol::Cigi) cigi_source = &src;
  std::unique_ptr<io::net::UdpSender> cigi_reply;
  if (s.cigi_reply) cigi_reply = std::make_unique<io::net::UdpSender>(*s.cigi_reply);
  std::unique_ptr<io::RecordingWriter> recorder;
  if (s.record) recorder = std::make_unique<io::RecordingWriter>(*s.record);

  ScenarioRunner runner(std::move(scenario), run);
  PoseFeed feed(runner.heightfield());
  feed.set_latency_mode(s.latency);
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
  if (cigi_reply || s.udp || cigi_source)
    services = std::make_unique<HostServices>(runner.heightfield(), runner.scene().earth_radius_m(),
                                              geodetic_placer(runner.heightfield()),
                                              local_to_geodetic(runner.heightfield()), HostServicesOptions{},
                                              &runner.scene().height_pyramid());
  // The rest of what a CIGI host sends: time of day, visibility, position
  // and collision requests, packets counted as not supported.
  std::unique_ptr<HostEnvironment> environment;
  if (cigi_source)
    environment = std::make_unique<HostEnvironment>(*services, local_to_geodetic(runner.heightfield()),
                                                    runner.scene().shading().fog_visibility_m);
  // The host's Weather Control may bring clouds at any frame: the frame
  // log's columns carry the cloud pass from the start.
  if (environment)
    for (auto& channel : runner.channels()) channel.renderer->set_clouds_may_come(true);
  // Every entity the host places besides the ownship, clamped to the
  // surface host queries answer from.
  std::unique_ptr<io::EntityTable> entities;
  double entity_time_s = 0.0;  // the time entities are placed at: the frame's start
  io::Pose frame_pose = initial;
  if (environment) {
    entities = std::make_unique<io::EntityTable>(
        geodetic_placer(runner.heightfield()), [&services](double x, double y) -> std::optional<io::SurfaceSample> {
          const auto s = services->surface_at(x, y);
          if (!s) return std::nullopt;
          return io::SurfaceSample{s->height_m, s->normal};
        });
    auto entity_pose = [&](std::uint16_t id) -> std::optional<io::Pose> {
      const auto e = entities->pose_of(id, entity_time_s, frame_pose);
      return e ? std::optional(e->pose) : std::nullopt;
    };
    services->set_entity_lookup(entity_pose);
    runner.set_entity_lookup(entity_pose);  // views riding on entities
    environment->set_entity_lookup([&](std::uint16_t id, std::optional<std::uint8_t> part) -> std::optional<io::Pose> {
      if (part) return entities->part_pose_of(id, *part, entity_time_s, frame_pose);
      const auto e = entities->pose_of(id, entity_time_s, frame_pose);
      return e ? std::optional(e->pose) : std::nullopt;
    });
  }
  std::size_t entities_placed_max = 0;  // the most entities one frame placed
  DrawnSurface drawn(runner);
  if (services && s.host_surface_drawn)
    services->set_drawn_height([&drawn](double x, double y) { return drawn.level0_height_at(x, y); });
  std::unique_ptr<ControlSurface> control;  // Modbus
  if (s.modbus) control = make_modbus_surface(*s.modbus, s.modbus_writers, runner, s.latency, s.quiet);
  std::optional<io::Pose> last_pose;  // for freeze
  std::unique_ptr<ExtraPoseSource> extra_source;  // SocketCAN
  if (s.can) extra_source = make_can_source(*s.can);

  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  RunOutputs outputs(out, "ig serve", !s.quiet && isatty(STDERR_FILENO));
  const double period = 1.0 / s.rate_hz;
  const double start = io::net::steady_now_s();
  double next_tick = start;
  const int total = s.frames.value_or(0);
  // capture.times_s and capture.every_s: seconds since the IG started; the
  // first frame at or after each.
  CaptureSchedule captures(runner.scenario(), 0.0);
  double display_lead_s = 0.0;  // frame start -> frame complete, smoothed (the latest mode's lead)
  // Freed per-frame memory back to the system every 10 s (session/heap_trim.h):
  // resident memory follows the frames in flight, not the largest frame so far.
  HeapTrim heap_trim(10.0);
  std::uint64_t sync_waits = 0, sync_frames = 0;
  std::optional<std::array<std::uint8_t, io::wire::kCigiStartOfFrameSize>> last_sof;
  // Datagrams from anyone but the source's host are counted and dropped,
  // with one line the first time.
  auto accept_sender = [&](Source& src, const sockaddr_in& from) {
    const auto verdict = src.senders.check(from);
    const char* name = io::protocol_name(src.protocol);
    if (verdict == io::net::SenderFilter::Verdict::LockedOn && !s.quiet)
      std::cerr << "ig serve: " << name << ": taking datagrams from " << io::net::to_string(from)
                << " only (the first sender; --host ADDR[:PORT] names the host)\n";
    if (verdict == io::net::SenderFilter::Verdict::FirstForeign)
      std::cerr << "ig serve: " << name << ": a datagram from " << io::net::to_string(from)
                << ", not the host: dropped; every such datagram is counted (foreign_datagrams)\n";
    return io::net::SenderFilter::accepted(verdict);
  };
  auto poll_source = [&](Source& src, std::size_t max_datagrams) {
    return src.socket->poll(
        [&](std::span<const std::uint8_t> d, double t, const sockaddr_in& from) {
          // Native queries change nothing: answered to whoever asks.
          if (services && src.protocol == io::Protocol::Native && io::wire::is_native_query(d)) {
            if (const auto answer = services->answer_native(d)) src.socket->send_to(*answer, from);
            return;
          }
          if (!accept_sender(src, from)) return;
          if (recorder) recorder->write(src.protocol, d, t);
          if (src.protocol != io::Protocol::Cigi) {
            feed.intake().handle(src.protocol, d, t);
            return;
          }
          // One decode; each part takes its packets.
          const io::wire::CigiHostDatagram cigi = io::wire::decode_cigi(d);
          feed.intake().handle_cigi(cigi, t);
          if (services && cigi_reply) services->take(cigi.requests);  // answered only with somewhere to send them
          views.take(cigi.views, channel_spec);
          if (environment) environment->take(cigi.host);
          if (entities) {
            if (cigi.host.ig_mode == io::wire::kCigiModeStandby) entities->clear();  // reset: the host starts over
            entities->take(cigi.entities, cigi.host.rates, t);
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
        if (s.seconds && io::net::steady_now_s() - start >= *s.seconds) break;
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
    const bool last = (s.frames && k == *s.frames - 1) ||
                      (s.seconds && frame_start - start + (sync ? 0.0 : period) >= *s.seconds) || g_stop;
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
          if (!s.quiet)
            std::cerr << "ig serve: modbus: latency mode " << io::latency_mode_name(*applied.latency) << "\n";
        }
      }
    }
    const auto t0 = std::chrono::steady_clock::now();
    // Frozen: the last pose again; the sources are still drained and counted.
    const io::Pose pose = frozen && last_pose ? *last_pose : feed.pose_at(frame_start, initial, display_lead_s);
    last_pose = pose;
    const double pose_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (environment) apply_host_environment(*environment, runner, frame_start - start, pose);
    if (entities) {
      entity_time_s = frame_start;
      frame_pose = pose;
      const auto placed = entities->poses_at(entity_time_s, pose);
      entities_placed_max = std::max(entities_placed_max, placed.size());
      std::vector<render::EntityInstance> drawn;
      drawn.reserve(placed.size());
      for (const auto& e : placed) {
        render::EntityInstance d{e.id, e.type, e.pose.position, e.pose.attitude, e.alpha, {}};
        for (const auto& [id, p] : *e.parts)
          d.parts.push_back({id, p.enabled, {p.x_m.value_or(0), p.y_m.value_or(0), p.z_m.value_or(0)},
                             {p.roll_deg.value_or(0), p.pitch_deg.value_or(0), p.yaw_deg.value_or(0)}});
        drawn.push_back(std::move(d));
      }
      runner.set_entities(std::move(drawn));
      for (const auto& m : entities->take_messages()) environment->message(m);
      if (auto* r = runner.entity_renderer())
        for (const auto& m : r->take_messages()) environment->message(m);
    }
    const FrameResult f = runner.render_pose(k, frame_start - start, pose, pose_ms);
    const double complete = io::net::steady_now_s();  // the renderer ends with glFinish
    feed.frame_complete(complete);
    display_lead_s += 0.1 * (std::min(complete - frame_start, 2.0 * period) - display_lead_s);
    if (cigi_reply) {
      last_sof = io::wire::encode_cigi_start_of_frame(
          std::uint32_t(k), feed.intake().last_host_frame().value_or(0),
          std::uint32_t(std::llround((frame_start - start) * 1e5)),
          environment ? environment->ig_mode() : io::wire::kCigiModeOperate, false);
      auto datagram = services->frame_datagram(*last_sof, pose);  // with this frame's answers
      if (environment)
        environment->append_frame_packets(pose, view_poses(runner), runner.scene().shading().fog_visibility_m,
                                          datagram, io::wire::kCigiMaxDatagram);
      cigi_reply->send(datagram);
    } else if (services) {
      services->answer_frame(pose);  // the frame ends: a new native budget
    }
    outputs.frame(runner, f, capture, last, total, [&](std::vector<stats::Cell>& row) { feed.append_columns(row); });
    if (control)
      control->publish(k + 1, frame_start, io::net::steady_now_s(), feed, last,
                       extra_source ? extra_source->status() : ExtraSourceStatus{});
    if (last || (!runner.context().headless() && runner.window_closed())) break;
    heap_trim.maybe_trim(io::net::steady_now_s());
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
  std::uint64_t kernel_stamped = 0, datagrams = 0, foreign = 0;
  nlohmann::json senders = nlohmann::json::object();
  for (const auto& src : sources) {
    kernel_stamped += src.socket->stats().kernel_timestamps;
    datagrams += src.socket->stats().datagrams;
    foreign += src.senders.foreign();
    auto& entry = senders[io::protocol_name(src.protocol)];
    entry["foreign_datagrams"] = src.senders.foreign();
    if (const auto locked = src.senders.locked()) entry["locked_onto"] = *locked;
  }
  nlohmann::json allowed = nlohmann::json::array();
  for (const auto& h : hosts) allowed.push_back(io::net::to_string(h));
  nlohmann::json extra = {{"pose_intake", feed.summary()},
                          {"rate_hz", s.rate_hz},
                          {"latency_mode", io::latency_mode_name(feed.filter().latency_mode())},
                          {"datagrams", datagrams},
                          {"foreign_datagrams", foreign},
                          {"senders", {{"hosts", allowed}, {"sources", senders}}},
                          {"kernel_receive_timestamps", kernel_stamped}};
  if (cigi_source) extra["cigi_sync"] = {{"frames", sync_frames}, {"waits", sync_waits}};
  if (services) extra["host_services"] = services->summary();
  if (cigi_source) extra["view_control"] = views.summary();
  if (environment) extra["cigi"] = environment->summary();
  if (entities) {
    extra["entities"] = entities->summary();
    extra["entities"]["placed_max"] = entities_placed_max;
  }
  if (recorder) extra["recording"] = {{"file", *s.record}, {"datagrams", recorder->count()}};
  if (extra_source) extra[extra_source->summary_key()] = extra_source->summary();
  if (control) extra["modbus"] = control->summary();
  extra["heap_trim"] = heap_trim.summary();
  return outputs.finish(runner, config, extra);
}

}  // namespace ig::session
