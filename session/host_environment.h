#pragma once
// What a CIGI host says beyond poses and terrain queries (docs/protocol.md,
// "CIGI 3.3: every packet"): the time of day and visibility it sets, the
// positions and collision segments it asks about, the environmental
// conditions it requests, and the packets this IG does not act on (counted
// by opcode, each kind answered once with an IG Message). No sockets and no
// GL: the live loop hands in the host's datagrams, applies changes() at the
// frame boundary and appends append_frame_packets() to the frame's datagram.
// Weather Control's cloud layers become options::CloudLayers (docs/protocol.md):
// a layer whose fields are out of range is refused and counted, not drawn.

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <span>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/pose.h"
#include "io/wire/cigi_environment.h"
#include "options/cloud_options.h"
#include "options/shading_options.h"
#include "session/host_services.h"

namespace ig::session {

class HostEnvironment {
 public:
  // services: the terrain the collision segments are tested against (the
  // exact surface HAT/HOT and line-of-sight answer from); visibility_m: the
  // IG's own (the scenario's fog) until the host sets one.
  HostEnvironment(HostServices& services, LocalToGeodetic to_geodetic, double visibility_m);

  // Every datagram from the CIGI host.
  void take(const io::wire::CigiHostPackets& packets);
  void take(std::span<const std::uint8_t> datagram);  // decodes, then the above

  // What the host changed since the last call, for the frame about to render.
  struct Changes {
    // Celestial Sphere Control: the UTC date and time, and whether the clock
    // runs from it (ephemeris enabled) or holds it.
    std::optional<options::UtcDateTime> time_utc;
    bool clock_runs = true;
    // The visibility in force at the eye, when it changed: the lowest of the
    // global weather layers without cloud (Weather Control, scope global,
    // enabled; a cloud layer's visibility is drawn inside it) whose
    // altitude band holds the eye, else Atmosphere Control's global
    // visibility, else the IG's own.
    std::optional<double> visibility_m;
    // The cloud layers, when they changed: every global Weather Control layer
    // with a cloud type, by layer id (the scene checks each against the
    // terrain and its limit of layers: TerrainScene::set_clouds).
    std::optional<options::CloudLayers> clouds;
  };
  // `eye_altitude_m`: the ownship's, in the terrain's heights; `today`: the
  // date to use where the host's date is not valid (asked only then).
  Changes changes(double eye_altitude_m, const std::function<options::UtcDateTime()>& today);

  // The frame's packets for the host: Position Responses, Collision
  // Detection Segment Notifications, Weather Conditions Responses and IG
  // Messages, appended to `out` while it stays within max_bytes.
  // `views`: each view's eye (index = view id); `visibility_m`: in force.
  void append_frame_packets(const io::Pose& ownship, std::span<const io::Pose> views, double visibility_m,
                            std::vector<std::uint8_t>& out, std::size_t max_bytes);

  // Where entity `id` (part: its articulated part) is now; nullopt when the
  // IG has no such active entity. Unset: only the ownship and the views
  // are known.
  using EntityLookup = std::function<std::optional<io::Pose>(std::uint16_t id, std::optional<std::uint8_t> part)>;
  void set_entity_lookup(EntityLookup lookup) { entity_lookup_ = std::move(lookup); }

  // A refusal found where the host's packets are applied (the scene's
  // cloud checks): counted under `reason` and sent once as an IG Message.
  void refuse(const std::string& reason, const std::string& text);

  // The IG's own notices to the host (a refused database load, an opcode
  // not supported, ...): each text sent once, with the next frame.
  void message(const std::string& text);

  struct Counters {
    // Packets taken and answers sent, by summary.json name
    // ("celestial_sphere_controls", "position_responses", ...).
    std::map<std::string, std::uint64_t> packets;
    std::map<int, std::uint64_t> unsupported;       // opcode -> packets
    std::map<std::string, std::uint64_t> rejected;  // reason -> packets
  };
  const Counters& counters() const { return counters_; }
  // The IG mode the host asks for (IG Control): reset / standby (0) or
  // operate (1; debug counts as operate), as the Start Of Frame reports it.
  // Entering reset / standby from operate drops what the host had set up:
  // continuous Position Requests and collision segments (the live loop
  // drops the entities).
  std::uint32_t ig_mode() const { return ig_mode_; }
  nlohmann::json summary() const;

 private:
  std::optional<io::wire::CigiPositionResponse> position_of(const io::wire::CigiPositionRequest& r,
                                                             const io::Pose& ownship,
                                                             std::span<const io::Pose> views) const;
  HostServices& services_;
  LocalToGeodetic to_geodetic_;
  std::optional<io::wire::CigiCelestialSphere> celestial_;  // not yet applied
  std::optional<double> atmosphere_visibility_m_;
  std::optional<io::wire::CigiAtmosphere> atmosphere_;  // the last Atmosphere Control, echoed by Weather Conditions
  std::map<int, io::wire::CigiWeatherControl> layers_;      // global weather layers without cloud, by layer id
  std::map<int, options::CloudLayer> clouds_;               // the cloud layers among them, as checked
  bool clouds_changed_ = false;
  void take_weather(const io::wire::CigiWeatherControl& w);
  double own_visibility_m_;
  double visibility_in_force_m_;
  std::vector<io::wire::CigiPositionRequest> one_shot_;
  std::map<std::pair<int, int>, io::wire::CigiPositionRequest> continuous_;  // (class, object)
  std::map<std::pair<int, int>, io::wire::CigiCollisionSegment> segments_;  // (entity, segment id)
  EntityLookup entity_lookup_;
  std::vector<io::wire::CigiEnvironmentRequest> conditions_;
  std::vector<std::string> messages_;  // to send
  std::set<std::string> announced_;    // every text queued so far
  std::uint32_t ig_mode_ = io::wire::kCigiModeOperate;
  Counters counters_;
};

}  // namespace ig::session
