#pragma once
// From datagrams to the pose filter: decode by protocol, place geodetic
// positions on the terrain, count what was accepted and why anything was
// rejected, feed the filter. The same path serves live sockets and
// recordings, so a replay goes through exactly the decoders and filter the
// live run used.

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>

#include <glm/vec3.hpp>

#include "io/filter/pose_filter.h"
#include "io/wire/cigi_environment.h"
#include "io/wire/cigi_host_datagram.h"
#include "io/wire/pose_message.h"

namespace ig::io {

// UDP formats first, then the CAN formats (which arrive already decoded by
// io/can/can_pose_source.h, through handle_pose).
enum class Protocol : std::uint8_t { Native = 0, Cigi = 1, FgNetFdm = 2, CanAerospace = 3, CanFd = 4 };
inline constexpr int kProtocolCount = 5;
const char* protocol_name(Protocol p);  // "native", "cigi", "fgfdm", "canaerospace", "canfd"

struct SourceCounters {
  std::uint64_t ok = 0;   // decoded into a pose and handed to the filter
  std::uint64_t bad = 0;  // rejected (malformed, out of range, unplaceable)
  std::uint64_t no_pose = 0;  // valid but without an ownship pose (CIGI without entity 0)
  std::map<std::string, std::uint64_t> reasons;  // reject name -> count
};

// Geodetic (lat deg, lon deg, alt m) -> terrain-local ENU metres; nullopt when
// the scene cannot place it (no georeference).
using GeodeticToLocal = std::function<std::optional<glm::dvec3>(double lat_deg, double lon_deg, double alt_m)>;

class PoseIntake {
 public:
  PoseIntake(PoseFilter& filter, GeodeticToLocal to_local);
  // Decodes one datagram received at receive_time_s (IG clock) and, when it
  // carries a valid pose, feeds the filter. Never throws.
  void handle(Protocol protocol, std::span<const std::uint8_t> datagram, double receive_time_s);
  // A CIGI datagram decoded once (wire/cigi_host_datagram.h): its ownship
  // pose, IG Control and ownship Rate Control. handle(Cigi, ...) decodes and
  // comes here.
  void handle_cigi(const wire::CigiHostDatagram& datagram, double receive_time_s);
  // A pose some transport already decoded and validated (CAN): placed and
  // fed like a datagram's pose.
  void handle_pose(Protocol protocol, const wire::PoseMessage& pose, double receive_time_s);

  const SourceCounters& counters(Protocol p) const { return counters_[int(p)]; }
  std::uint64_t total_ok() const;
  std::uint64_t total_bad() const;
  // Protocol of the newest pose handed to the filter ("" before any).
  std::string last_source() const { return last_source_; }
  // CIGI: the newest host frame counter seen in an IG Control packet.
  std::optional<std::uint32_t> last_host_frame() const { return last_host_frame_; }
  // CIGI: datagrams that carried an IG Control (one per host frame; CIGI
  // synchronous operation renders one IG frame for each).
  std::uint64_t ig_controls() const { return ig_controls_; }
  // CIGI Rate Control for the ownship: its rates ride on every CIGI pose
  // after it (the filter dead-reckons with them between host frames) until
  // the next one; all-zero rates hand back to rates derived from the poses.
  const std::optional<wire::CigiRateControl>& cigi_rates() const { return cigi_rates_; }

 private:
  void reject(Protocol p, const std::string& reason);
  void finish(Protocol p, const wire::DecodeResult& r, double receive_time_s);
  PoseFilter& filter_;
  GeodeticToLocal to_local_;
  std::array<SourceCounters, kProtocolCount> counters_;
  std::string last_source_;
  std::optional<std::uint32_t> last_host_frame_;
  std::uint64_t ig_controls_ = 0;
  std::optional<wire::CigiRateControl> cigi_rates_;
};

}  // namespace ig::io
