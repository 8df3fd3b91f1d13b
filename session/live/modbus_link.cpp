// Compiled only with Modbus (IG_WITH_MODBUS); see modbus_link.h.
#include "session/live/modbus_link.h"

#include <algorithm>
#include <cmath>
#include <iostream>

#include <stdexcept>

#include "io/net/sender_filter.h"

namespace ig::session {

ModbusLink::ModbusLink(const std::string& endpoint, const std::vector<std::string>& writers, ScenarioRunner& runner,
                       io::LatencyMode initial_latency, bool quiet)
    : runner_(runner), quiet_(quiet) {
  const auto& r = runner.scenario().render;
  active_.a1 = float(r.twolevel.a1);
  active_.a2 = float(r.twolevel.a2);
  active_.alpha = float(r.twolevel.alpha);
  active_.level0_budget = std::uint32_t(r.twolevel.level0_budget);
  active_.fog_visibility_m = float(r.shading.fog_visibility_m);
  active_.latency_mode = std::uint16_t(initial_latency);
  auto options = io::control::parse_modbus_endpoint(endpoint);
  for (const auto& w : writers) {
    const auto host = io::net::parse_host_pattern(w);
    if (host.port) throw std::invalid_argument("--modbus-writer " + w + ": an address, without a port");
    options.writers.push_back(host.address);
  }
  server_ = std::make_unique<io::control::ModbusServer>(options, active_);
  if (!quiet_)
    std::cerr << "ig serve: Modbus TCP on " << endpoint.substr(0, endpoint.rfind(':')) << ":" << server_->port()
              << (writers.empty() ? " (writes from any address; --modbus-writer ADDR limits them)" : "") << "\n";
}

ModbusLink::Applied ModbusLink::apply_controls() {
  const auto u = server_->take_controls();
  const auto& c = u.controls;
  frozen_ = c.freeze;
  wireframe_ = c.wireframe;
  for (auto& ch : runner_.channels()) {
    ch.renderer->set_wireframe(c.wireframe);
    if (u.thresholds) ch.method->tune({std::pair<double, double>(c.a1, c.a2)});
  }
  if (u.fog) runner_.scene().set_fog_visibility(c.fog_visibility_m);
  if (u.rebuild && (c.alpha != active_.alpha || c.level0_budget != active_.level0_budget)) {
    // Level0 and the band width are built with the method: rebuild it now,
    // at the frame boundary (this frame pays the Level0 build).
    options::TwoLevelOptions t = runner_.scenario().render.twolevel;
    t.alpha = c.alpha;
    t.level0_budget = int(c.level0_budget);
    t.a1 = c.a1;
    t.a2 = c.a2;
    runner_.rebuild_method(t);
    active_.alpha = c.alpha;
    active_.level0_budget = c.level0_budget;
    if (!quiet_)
      std::cerr << "ig serve: modbus: rebuilt the LOD method (level0_budget " << c.level0_budget << ", band_alpha "
                << c.alpha << ")\n";
  }
  Applied a;
  a.capture = u.capture;
  a.frozen = frozen_;
  if (u.latency) a.latency = io::LatencyMode(c.latency_mode);
  return a;
}

void ModbusLink::publish(int frames, double frame_start_s, double frame_end_s, PoseFeed& feed, bool last,
                         const ExtraSourceStatus& source) {
  namespace ctl = io::control;
  const double frame_us = (frame_end_s - frame_start_s) * 1e6;
  window_.push_back({frame_end_s, frame_us});
  while (!window_.empty() && window_.front().first < frame_end_s - 1.0) window_.erase(window_.begin());
  std::vector<double> v;
  for (const auto& w : window_) v.push_back(w.second);
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());

  ctl::IgStatus s;
  const bool received = !feed.intake().last_source().empty();
  s.state = last       ? ctl::IgState::Stopping
            : frozen_  ? ctl::IgState::Frozen
            : received ? ctl::IgState::Running
                       : ctl::IgState::WaitingPose;
  s.frame_counter = std::uint32_t(frames);
  s.last_frame_us = std::uint32_t(std::lround(frame_us));
  s.median_frame_us = std::uint32_t(std::lround(v[v.size() / 2]));
  const auto& ch = runner_.channels().front();
  s.triangles = std::uint32_t(std::clamp<long long>(ch.last.method.triangles, 0, 0xFFFFFFFFLL));
  std::uint16_t flags = 0;
  if (const auto level = ch.method->level_status()) {
    s.level1_size = std::uint16_t(level->level1_size);
    s.level1_ratio = float(level->coverage_ratio);
    flags |= ctl::kFlagTwoLevel;
  }
  const double pose_age_ms = feed.pose_age_ms();
  s.pose_age_ms = pose_age_ms < 0 ? 0xFFFFFFFFu : std::uint32_t(std::min(std::lround(pose_age_ms), 0xFFFFFFFEL));
  auto counts = [&](io::Protocol p) {
    const auto& c = feed.intake().counters(p);
    return ctl::PacketCounts{std::uint32_t(c.ok), std::uint32_t(c.bad)};
  };
  s.native = counts(io::Protocol::Native);
  s.cigi = counts(io::Protocol::Cigi);
  s.fgfdm = counts(io::Protocol::FgNetFdm);
  s.can_link = source.link;
  s.can_poses = source.poses;
  s.can_rejected = source.rejected;
  s.can_error_frames = source.error_frames;
  if (frozen_) flags |= ctl::kFlagFrozen;
  if (wireframe_) flags |= ctl::kFlagWireframe;
  if (received) flags |= ctl::kFlagPoseReceived;
  s.flags = flags;
  server_->publish(s);
}

nlohmann::json ModbusLink::summary() const {
  const auto c = server_->counters();
  return {{"port", server_->port()},
          {"requests", c.requests},
          {"exceptions", c.exceptions},
          {"writes_applied", c.writes_applied},
          {"writes_refused", c.writes_refused},
          {"clients_accepted", c.clients_accepted},
          {"clients_dropped", c.clients_dropped}};
}

void check_modbus_endpoint(const std::string& endpoint) {
  try {
    io::control::parse_modbus_endpoint(endpoint);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--modbus ") + e.what());
  }
}

std::unique_ptr<ControlSurface> make_modbus_surface(const std::string& endpoint, const std::vector<std::string>& writers,
                                                    ScenarioRunner& runner, io::LatencyMode initial_latency,
                                                    bool quiet) {
  return std::make_unique<ModbusLink>(endpoint, writers, runner, initial_latency, quiet);
}

}  // namespace ig::session
