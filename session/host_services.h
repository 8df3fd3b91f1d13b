#pragma once
// CIGI host services for ig serve: HAT/HOT and line-of-sight requests taken
// from the host's datagrams, answered once per IG frame from the drawn
// full-resolution terrain (terrain/terrain_query.h), within a per-frame
// budget; the rest wait for the next frame. Periodic requests (update
// period n > 0) are answered every n-th frame until the host sends the same
// id with period 0. No sockets here: the frame loop hands in datagrams and
// sends what frame_datagram() returns (docs/host-services.md).

#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "io/pose.h"
#include "io/pose_intake.h"
#include "io/wire/cigi.h"
#include "io/wire/cigi_queries.h"
#include "io/wire/native_query.h"
#include "terrain/terrain_query.h"

namespace ig::session {

struct HostServicesOptions {
  // Answers per frame (the rest wait): bounds the CPU a frame spends here.
  std::size_t max_hat_hot_per_frame = 2000;
  std::size_t max_los_per_frame = 200;
  // Responses per IG datagram (Start Of Frame included): one UDP datagram.
  std::size_t max_datagram_bytes = 60000;
  // Requests waiting beyond this are refused (counted "queue-full").
  std::size_t max_pending = 20000;
  // Periodic requests held at once (more are refused, "too-many-periodic").
  std::size_t max_periodic = 1024;
};

// Local ENU -> latitude, longitude, altitude (scene_setup.h local_to_geodetic).
using LocalToGeodetic = std::function<std::optional<glm::dvec3>(const glm::dvec3&)>;

class HostServices {
 public:
  // pyramid: the scene's min/max pyramid of hf to share (nullptr: build one).
  HostServices(const terrain::Heightfield& hf, double earth_radius_m, io::GeodeticToLocal to_local,
               LocalToGeodetic to_geodetic, HostServicesOptions options = {},
               const terrain::HeightPyramid* pyramid = nullptr);

  // "As drawn" HAT/HOT: where this returns a height (Level0 is drawn there,
  // session/drawn_surface.h), answer from it instead of the full-resolution
  // surface. Unset: full resolution everywhere (the default).
  using DrawnHeight = std::function<std::optional<double>(double x_m, double y_m)>;
  void set_drawn_height(DrawnHeight f) { drawn_height_ = std::move(f); }

  // Where entity `id` (not 0) is now, for requests relative to it; nullopt:
  // no such entity (the answer's valid flag is clear). Unset: only the
  // ownship is known.
  using EntityLookup = std::function<std::optional<io::Pose>(std::uint16_t id)>;
  void set_entity_lookup(EntityLookup f) { entity_lookup_ = std::move(f); }

  // Every datagram from the CIGI host: its requests are queued.
  void take(const io::wire::CigiRequests& requests);
  void take(std::span<const std::uint8_t> datagram);  // decodes, then the above

  // This frame's answers: the due periodic requests, then the queue in
  // arrival order, up to the budget. `ownship` is the pose the frame
  // renders (entity 0, for entity-relative requests).
  std::vector<io::wire::CigiResponse> answer_frame(const io::Pose& ownship);
  // The IG -> host datagram for this frame: `sof` followed by answer_frame's
  // responses, in the Start Of Frame's byte order (this machine's).
  std::vector<std::uint8_t> frame_datagram(const std::array<std::uint8_t, io::wire::kCigiStartOfFrameSize>& sof,
                                           const io::Pose& ownship);

  // A native query ("IGQR", docs/protocol.md) answered at once, within the
  // same per-frame budget (nullopt: malformed or over budget, counted).
  std::optional<std::array<std::uint8_t, io::wire::kNativeQuerySize>> answer_native(
      std::span<const std::uint8_t> datagram);
  io::wire::NativeAnswer answer(const io::wire::NativeQuery& query);

  // One request answered now, outside the queue and the budget (library use).
  io::wire::CigiResponse answer(const io::wire::CigiRequest& request, const io::Pose& ownship);
  // A collision segment cast for the IG's own notifications: the same
  // answer, counted as a cast, not as a host request answered.
  io::wire::CigiResponse cast_collision_segment(const io::wire::LosSegmentRequest& segment, const io::Pose& ownship);

  struct Counters {
    std::uint64_t requests = 0;     // well-formed requests taken
    std::uint64_t answered = 0;     // responses to host requests (CIGI and native)
    std::uint64_t answered_hat_hot = 0, answered_los = 0;  // the CIGI ones by kind
    std::uint64_t collision_casts = 0;  // segments cast for collision notifications (not requests)
    std::uint64_t invalid = 0;      // responses with the valid flag clear
    std::uint64_t deferred = 0;     // answered in a later frame than received (budget)
    std::uint64_t periodic_answers = 0;
    std::uint64_t cancelled = 0;    // periodic requests ended by the host
    std::uint64_t native_answered = 0;  // native queries answered
    std::map<std::string, std::uint64_t> dropped;  // reason -> count (malformed, refused)
  };
  const Counters& counters() const { return counters_; }
  std::size_t pending() const { return queue_.size(); }
  std::size_t periodic() const { return periodic_.size(); }
  double last_frame_ms() const { return last_frame_ms_; }
  nlohmann::json summary() const;
  const terrain::TerrainQuery& terrain() const { return query_; }
  // The surface HAT/HOT is answered from at a local point (water at its
  // level; as drawn when set so): what entities are clamped to.
  std::optional<terrain::SurfacePoint> surface_at(double x_m, double y_m) const { return surface_for_hot(x_m, y_m); }

 private:
  struct Pending {
    io::wire::CigiRequest request;
    std::uint64_t frame;  // IG frame (answer_frame calls) it arrived before
  };
  struct Periodic {
    io::wire::CigiRequest request;
    std::uint64_t next_frame;
  };
  void drop(const std::string& reason) { ++counters_.dropped[reason]; }
  std::optional<glm::dvec3> place(const glm::dvec3& p, io::wire::CigiCoords c, bool entity_known,
                                  const io::Pose& entity);
  // `reference`: the pose entity-relative points are relative to (the
  // request's entity); `entity_known`: the IG has that entity.
  io::wire::HatHotResponse hat_hot(const io::wire::HatHotRequest& r, const io::Pose& reference, bool entity_known);
  // `ownship`: the frame's, for a destination relative to entity 0.
  io::wire::LosResponse los_segment(const io::wire::LosSegmentRequest& r, const io::Pose& reference,
                                    bool entity_known, const io::Pose& ownship);
  io::wire::LosResponse los_vector(const io::wire::LosVectorRequest& r, const io::Pose& reference, bool entity_known);
  void fill_hit(io::wire::LosResponse& out, const std::optional<terrain::LosHit>& hit, io::wire::CigiCoords coords,
                const io::Pose& ownship);
  static int kind(const io::wire::CigiRequest& r) { return int(r.index()); }
  io::wire::CigiResponse respond(const io::wire::CigiRequest& request, const io::Pose& ownship);
  // The surface a HAT/HOT is answered from (full resolution, or as drawn).
  std::optional<terrain::SurfacePoint> surface_for_hot(double x_m, double y_m) const;

  terrain::TerrainQuery query_;
  io::GeodeticToLocal to_local_;
  LocalToGeodetic to_geodetic_;
  DrawnHeight drawn_height_;
  EntityLookup entity_lookup_;
  HostServicesOptions options_;
  std::deque<Pending> queue_;
  std::map<std::pair<int, std::uint16_t>, Periodic> periodic_;  // (request kind, id)
  std::uint64_t frame_ = 0;
  std::size_t native_hat_hot_ = 0, native_los_ = 0;  // answered natively this frame
  std::uint32_t host_frame_ = 0;
  Counters counters_;
  double last_frame_ms_ = 0.0, max_frame_ms_ = 0.0, sum_frame_ms_ = 0.0;
  std::uint64_t frames_with_work_ = 0;
};

}  // namespace ig::session
