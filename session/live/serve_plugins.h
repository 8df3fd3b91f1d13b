#pragma once
// ig serve's optional parts behind two small interfaces, so the frame loop
// has no build switches: an extra pose source (SocketCAN) and a control
// surface (Modbus). Which implementation a build gets is chosen by CMake
// (can_link.cpp or can_link_off.cpp, modbus_link.cpp or modbus_link_off.cpp);
// the "off" factories refuse the option with a clear message.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/filter/pose_filter.h"
#include "session/pose_feed.h"
#include "session/scenario_runner.h"

namespace ig::session {

// What a control surface reports about the extra pose source.
struct ExtraSourceStatus {
  std::uint16_t link = 0;  // 0 none, 1 receiving, 2 down (retrying)
  std::uint32_t poses = 0, rejected = 0, error_frames = 0;
};

class ExtraPoseSource {
 public:
  virtual ~ExtraPoseSource() = default;
  // Hands everything that has arrived to the feed, never waiting; says each
  // change of the link's state once on stderr.
  virtual void poll(PoseFeed& feed) = 0;
  virtual ExtraSourceStatus status() const = 0;
  virtual std::string summary_key() const = 0;  // its summary.json member
  virtual nlohmann::json summary() const = 0;
};

struct CanSourceSettings {
  std::string ifname;
  int altitude_id = 322;
  std::optional<int> node;
  double max_age_ms = 100.0;
  bool quiet = false;
};
// Throws std::invalid_argument when this ig was built without SocketCAN.
std::unique_ptr<ExtraPoseSource> make_can_source(const CanSourceSettings& settings);

class ControlSurface {
 public:
  struct Applied {
    bool capture = false;                    // capture this frame
    bool frozen = false;                     // render the last pose again
    std::optional<io::LatencyMode> latency;  // latency mode written
  };
  virtual ~ControlSurface() = default;
  // At the frame boundary, before rendering.
  virtual Applied apply_controls() = 0;
  // After each frame: the status snapshot clients read.
  virtual void publish(int frames, double frame_start_s, double frame_end_s, PoseFeed& feed, bool last,
                       const ExtraSourceStatus& source) = 0;
  virtual nlohmann::json summary() const = 0;
};
// Throws std::invalid_argument (message "--modbus ...") for a malformed
// endpoint, or when built without Modbus.
void check_modbus_endpoint(const std::string& endpoint);
// writers: the addresses Modbus writes are taken from (empty: any).
std::unique_ptr<ControlSurface> make_modbus_surface(const std::string& endpoint, const std::vector<std::string>& writers,
                                                    ScenarioRunner& runner, io::LatencyMode initial_latency,
                                                    bool quiet);

}  // namespace ig::session
