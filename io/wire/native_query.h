#pragma once
// Native host services ("IGQR" request, "IGQA" answer, version 1): height of
// terrain and line of sight over the native pose port, fixed 96 bytes,
// little-endian, CRC-32 trailer like the pose datagram. Layout and rules:
// docs/protocol.md, "Native host services".

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include <glm/vec3.hpp>

namespace ig::io::wire {

inline constexpr std::size_t kNativeQuerySize = 96;
inline constexpr std::uint16_t kNativeQueryVersion = 1;
inline constexpr std::array<std::uint8_t, 4> kNativeQueryMagic{'I', 'G', 'Q', 'R'};
inline constexpr std::array<std::uint8_t, 4> kNativeAnswerMagic{'I', 'G', 'Q', 'A'};

enum class NativeQueryKind : std::uint8_t { Height = 1, LosSegment = 2, LosVector = 3 };

struct NativeQuery {
  NativeQueryKind kind = NativeQueryKind::Height;
  bool geodetic = false;  // points are lat deg, lon deg, alt m (else terrain-local ENU metres)
  std::uint32_t id = 0;
  glm::dvec3 a{0.0};  // the point (height), the source (LOS)
  glm::dvec3 b{0.0};  // segment: the destination; vector: the direction (ENU, any length)
  double min_range_m = 0.0, max_range_m = 0.0;  // vector only
};

struct NativeAnswer {
  NativeQueryKind kind = NativeQueryKind::Height;
  bool geodetic = false;  // point given as lat, lon, alt
  bool valid = false;     // the point / source is on the terrain's footprint
  bool hit = false;       // LOS: terrain was met (range, point, normal set)
  std::uint32_t id = 0;
  std::uint32_t ig_frame = 0;
  double hot_or_range_m = 0.0;  // height: HOT; LOS: range from the source
  double hat_m = 0.0;           // height only: the point's altitude minus HOT
  glm::dvec3 point{0.0};        // the surface point under / hit
  glm::dvec3 normal{0.0};       // unit, ENU
  std::uint32_t material = 0;   // what the surface is: 0 land, 1 water (terrain/surface_material.h)
};

// Why a query datagram was dropped.
enum class NativeQueryReject : std::uint8_t { WrongSize, BadMagic, BadVersion, BadCrc, BadKind, NonFinite, OutOfRange };
const char* native_query_reject_name(NativeQueryReject r);

// True when the datagram starts with "IGQR" (the pose port carries both).
bool is_native_query(std::span<const std::uint8_t> datagram);

struct NativeQueryResult {
  std::optional<NativeQuery> query;
  std::optional<NativeQueryReject> reject;
};
NativeQueryResult decode_native_query(std::span<const std::uint8_t> datagram);
std::array<std::uint8_t, kNativeQuerySize> encode_native_query(const NativeQuery& q);

std::array<std::uint8_t, kNativeQuerySize> encode_native_answer(const NativeAnswer& a);
// nullopt unless 96 bytes, "IGQA", version 1 and a good CRC.
std::optional<NativeAnswer> decode_native_answer(std::span<const std::uint8_t> datagram);

}  // namespace ig::io::wire
