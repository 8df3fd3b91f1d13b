#pragma once
// CIGI 3.3 view packets (host -> IG): View Control (opcode 16, 32 bytes: a
// view's offsets from its entity) and View Definition (opcode 21, 32 bytes:
// its frustum). Pure bytes, in the sender's byte order like the rest of the
// host datagram (docs/protocol.md, "CIGI 3.3 view control").

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "io/wire/cigi_queries.h"

namespace ig::io::wire {

inline constexpr std::uint8_t kCigiOpViewControl = 16;
inline constexpr std::uint8_t kCigiOpViewDefinition = 21;
inline constexpr std::size_t kCigiViewControlSize = 32;
inline constexpr std::size_t kCigiViewDefinitionSize = 32;

// View Control: [2] view id, [4] group id, [5] enable bits (0 x, 1 y, 2 z,
// 3 roll, 4 pitch, 5 yaw), [6] entity id, [8] x, [12] y, [16] z offsets
// (m, entity body axes), [20] roll, [24] pitch, [28] yaw (deg) - f32.
struct CigiViewControl {
  std::uint16_t view = 0;
  std::uint8_t group = 0;
  std::uint16_t entity = 0;
  std::optional<float> x_m, y_m, z_m, roll_deg, pitch_deg, yaw_deg;  // set when enabled
};

// View Definition: [2] view id, [4] group id, [5] enable bits (0 near, 1 far,
// 2 left, 3 right, 4 top, 5 bottom; 6-7 mirror mode), [6] bits 0-2 pixel
// replication, 3 projection (1 orthographic), 4 reorder, 5-7 view type,
// [8] near, [12] far (m), [16] left, [20] right, [24] top, [28] bottom
// half-angles (deg from the view vector: left and bottom negative) - f32.
struct CigiViewDefinition {
  std::uint16_t view = 0;
  std::uint8_t group = 0;
  bool orthographic = false;
  std::uint8_t mirror = 0;
  std::optional<float> near_m, far_m, left_deg, right_deg, top_deg, bottom_deg;
};

struct CigiViewPackets {
  std::vector<CigiViewControl> controls;
  std::vector<CigiViewDefinition> definitions;
  std::vector<QueryReject> rejects;  // wrong-size, truncated, non-finite, out-of-range
};

// The view packets of a host datagram (the same framing checks as
// decode_cigi_requests: nothing from a datagram the pose decoder rejects).
// Enabled angles must be finite and within +-360 deg (FOV half-angles within
// +-90, top > bottom and right > left when both given); offsets within 1e7 m.
CigiViewPackets decode_cigi_view_packets(std::span<const std::uint8_t> datagram);

std::array<std::uint8_t, kCigiViewControlSize> encode_cigi_view_control(const CigiViewControl& v, bool swap);
std::array<std::uint8_t, kCigiViewDefinitionSize> encode_cigi_view_definition(const CigiViewDefinition& v, bool swap);

}  // namespace ig::io::wire
