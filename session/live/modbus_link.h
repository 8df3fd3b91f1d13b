#pragma once
// ig serve's side of the Modbus server (docs/modbus.md): controls applied at
// the frame boundary, a status snapshot published after every frame. The
// server thread is never waited on: both are short copies under its mutex.
// Built only with IG_WITH_MODBUS (else modbus_link_off.cpp); ig serve sees
// it as a ControlSurface (serve_plugins.h).

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/control/modbus_server.h"
#include "io/filter/pose_filter.h"
#include "session/pose_feed.h"
#include "session/scenario_runner.h"
#include "session/live/serve_plugins.h"

namespace ig::session {

class ModbusLink final : public ControlSurface {
 public:
  // initial_latency: the mode the run starts in (the latency_mode register's first value).
  // writers: addresses writes are taken from (empty: any).
  ModbusLink(const std::string& endpoint, const std::vector<std::string>& writers, ScenarioRunner& runner,
             io::LatencyMode initial_latency, bool quiet);

  // Before rendering: freeze, wireframe, thresholds, fog, rebuilds, latency mode.
  Applied apply_controls() override;
  void publish(int frames, double frame_start_s, double frame_end_s, PoseFeed& feed, bool last,
               const ExtraSourceStatus& source) override;
  nlohmann::json summary() const override;

 private:
  ScenarioRunner& runner_;
  bool quiet_;
  io::control::IgControls active_;  // what the IG runs with (alpha, budget: as built)
  std::unique_ptr<io::control::ModbusServer> server_;
  bool frozen_ = false, wireframe_ = false;
  std::vector<std::pair<double, double>> window_;  // (frame end s, frame us) of the last second
};

}  // namespace ig::session
