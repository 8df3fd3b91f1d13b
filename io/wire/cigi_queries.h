#pragma once
// CIGI 3.3 host services on the wire: HAT/HOT and line-of-sight requests
// (host -> IG) and their responses (IG -> host). Pure bytes, no sockets.
// Layouts: docs/protocol.md, "CIGI 3.3 host services".
//
// Requests ride in host datagrams after the IG Control (cigi.h), in the
// sender's byte order (the IG Control's magic); responses ride in IG
// datagrams after a Start Of Frame, in the order the Start Of Frame's magic
// gives.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include <glm/vec3.hpp>

namespace ig::io::wire {

inline constexpr std::uint8_t kCigiOpHatHotRequest = 24;
inline constexpr std::uint8_t kCigiOpLosSegmentRequest = 25;
inline constexpr std::uint8_t kCigiOpLosVectorRequest = 26;
inline constexpr std::uint8_t kCigiOpHatHotResponse = 102;
inline constexpr std::uint8_t kCigiOpHatHotExtendedResponse = 103;
inline constexpr std::uint8_t kCigiOpLosResponse = 104;
inline constexpr std::uint8_t kCigiOpLosExtendedResponse = 105;
inline constexpr std::size_t kCigiHatHotRequestSize = 32;
inline constexpr std::size_t kCigiLosSegmentRequestSize = 64;
inline constexpr std::size_t kCigiLosVectorRequestSize = 56;
inline constexpr std::size_t kCigiHatHotResponseSize = 16;
inline constexpr std::size_t kCigiHatHotExtendedResponseSize = 40;
inline constexpr std::size_t kCigiLosResponseSize = 16;
inline constexpr std::size_t kCigiLosExtendedResponseSize = 56;

// Where a request's point is given: latitude deg, longitude deg, altitude m
// (WGS 84), or offsets in metres from an entity's reference point along its
// body axes (x forward, y right, z down).
enum class CigiCoords : std::uint8_t { Geodetic = 0, Entity = 1 };
enum class HatHotType : std::uint8_t { Hat = 0, Hot = 1, Extended = 2 };

struct HatHotRequest {
  std::uint16_t id = 0;
  HatHotType type = HatHotType::Hat;
  CigiCoords coords = CigiCoords::Geodetic;
  std::uint8_t update_period = 0;  // 0: answer once; n: every n-th frame until cancelled
  std::uint16_t entity = 0;
  glm::dvec3 point{0.0};  // lat, lon, alt or x, y, z offsets
  bool operator==(const HatHotRequest&) const = default;  // every field survives a round trip
};

struct LosSegmentRequest {
  std::uint16_t id = 0;
  bool extended = false;
  CigiCoords source_coords = CigiCoords::Geodetic;
  CigiCoords destination_coords = CigiCoords::Geodetic;
  CigiCoords response_coords = CigiCoords::Geodetic;
  bool destination_entity_valid = false;
  std::uint8_t alpha_threshold = 0;
  std::uint16_t entity = 0;
  glm::dvec3 source{0.0}, destination{0.0};
  std::uint32_t material_mask = 0;
  std::uint8_t update_period = 0;
  std::uint16_t destination_entity = 0;
  bool operator==(const LosSegmentRequest&) const = default;  // every field survives a round trip
};

struct LosVectorRequest {
  std::uint16_t id = 0;
  bool extended = false;
  CigiCoords source_coords = CigiCoords::Geodetic;
  CigiCoords response_coords = CigiCoords::Geodetic;
  std::uint8_t alpha_threshold = 0;
  std::uint16_t entity = 0;
  float azimuth_deg = 0, elevation_deg = 0;  // from true north / the horizon, or the entity's axes
  float min_range_m = 0, max_range_m = 0;
  glm::dvec3 source{0.0};
  std::uint32_t material_mask = 0;
  std::uint8_t update_period = 0;
  bool operator==(const LosVectorRequest&) const = default;  // every field survives a round trip
};

using CigiRequest = std::variant<HatHotRequest, LosSegmentRequest, LosVectorRequest>;
std::uint16_t request_id(const CigiRequest& r);
std::uint8_t update_period(const CigiRequest& r);

// Why a request packet was dropped.
enum class QueryReject : std::uint8_t {
  WrongSize,    // a request opcode whose size field is not the packet's size
  Truncated,    // size 0 or the packet runs past the datagram's end
  BadType,      // HAT/HOT request type 3
  NonFinite,    // NaN or Inf in a used field
  OutOfRange,   // latitude, longitude, altitude, offsets, angles or ranges out of range
};
const char* query_reject_name(QueryReject r);  // "wrong-size", "truncated", ...

struct CigiRequests {
  std::vector<CigiRequest> requests;  // in datagram order
  std::vector<QueryReject> rejects;   // one per dropped request packet
  std::size_t overflow = 0;           // well-formed requests past limits.max_requests
  bool byte_swapped = false;
  std::optional<std::uint32_t> host_frame;  // the IG Control's; nullopt: not a usable host datagram
};

// Every HAT/HOT and LOS request of a host datagram. A datagram the pose
// decoder rejects before its packets (size, no IG Control first, version,
// magic) gives no requests and no rejects (it is counted there). At most
// max_requests are returned; the datagram's later requests are dropped
// without a reject (the caller counts them from `overflow`).
struct CigiRequestLimits {
  std::size_t max_requests = 4096;
};
CigiRequests decode_cigi_requests(std::span<const std::uint8_t> datagram, const CigiRequestLimits& limits = {});

// Request encoders (hosts and tests), in this machine's order or swapped.
std::array<std::uint8_t, kCigiHatHotRequestSize> encode_cigi_hat_hot_request(const HatHotRequest& r, bool swap);
std::array<std::uint8_t, kCigiLosSegmentRequestSize> encode_cigi_los_segment_request(const LosSegmentRequest& r,
                                                                                     bool swap);
std::array<std::uint8_t, kCigiLosVectorRequestSize> encode_cigi_los_vector_request(const LosVectorRequest& r,
                                                                                   bool swap);

// ---------------------------------------------------------------- responses

// HAT/HOT Response (type Hat or Hot: one height) or Extended Response (both,
// plus material and the surface normal's azimuth from true north and
// elevation from the horizon). host_frame: its low 4 bits go on the wire.
struct HatHotResponse {
  std::uint16_t id = 0;
  bool valid = false;
  bool extended = false;
  HatHotType type = HatHotType::Hat;  // basic response: Hat or Hot
  std::uint32_t host_frame = 0;
  double hat_m = 0, hot_m = 0;
  std::uint32_t material = 0;
  float normal_azimuth_deg = 0, normal_elevation_deg = 0;
};

// LOS Response / Extended Response.
struct LosResponse {
  std::uint16_t id = 0;
  bool extended = false;
  bool valid = false;        // the request could be answered (source on the terrain's footprint ...)
  bool entity_valid = false;  // an entity was hit (never: only terrain is tested)
  bool range_valid = false;   // an intersection was found (extended; basic: range 0 without one)
  bool visible = false;       // segment: the destination is visible (no intersection)
  std::uint8_t response_count = 1;
  std::uint16_t entity = 0;
  std::uint32_t host_frame = 0;
  double range_m = 0;
  glm::dvec3 point{0.0};  // lat, lon, alt or entity offsets (extended)
  std::array<std::uint8_t, 4> rgba{0, 0, 0, 0};
  std::uint32_t material = 0;
  float normal_azimuth_deg = 0, normal_elevation_deg = 0;
};

using CigiResponse = std::variant<HatHotResponse, LosResponse>;

// Appends the response's packet (16, 40, 16 or 56 bytes) to out.
void append_cigi_response(const CigiResponse& r, bool swap, std::vector<std::uint8_t>& out);
std::size_t cigi_response_size(const CigiResponse& r);

// The responses in an IG -> host datagram that starts with a Start Of
// Frame (its magic gives the byte order); other packets are skipped.
// nullopt when the datagram does not start with a valid Start Of Frame or a
// packet runs past the end.
std::optional<std::vector<CigiResponse>> decode_cigi_responses(std::span<const std::uint8_t> datagram);

}  // namespace ig::io::wire
