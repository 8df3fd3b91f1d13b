#pragma once
// CIGI 3.3 packets that place and shape entities (host -> IG): Entity
// Control for any entity id and Articulated Part Control. Pure bytes, in the
// sender's byte order like the rest of the host datagram. Layouts:
// docs/protocol.md, "CIGI 3.3: entities".

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "io/wire/cigi_queries.h"

namespace ig::io::wire {

inline constexpr std::uint8_t kCigiOpArticulatedPartControl = 6;
inline constexpr std::size_t kCigiArticulatedPartControlSize = 32;

enum class CigiEntityState : std::uint8_t { Inactive = 0, Active = 1, Destroyed = 2 };
// Ground/ocean clamp: none; non-conformal (altitude = surface + offset);
// conformal (also pitch and roll to the surface normal).
enum class CigiClamp : std::uint8_t { None = 0, NonConformal = 1, Conformal = 2 };

// Entity Control: [2] entity id; [4] bits 0-1 state, bit 2 attached to the
// parent, bit 3 collision detection, bit 4 inherit alpha, bits 5-6 clamp;
// [5] animation bits; [6] alpha; [8] entity type; [10] parent id; [12] roll,
// [16] pitch, [20] yaw (deg, f32); [24] latitude / x, [32] longitude / y,
// [40] altitude / z (f64). Attached: x forward, y right, z down offsets (m)
// and angles relative to the parent. Clamped: altitude / z is the offset
// above the surface.
struct CigiEntityControl {
  std::uint16_t entity = 0;
  CigiEntityState state = CigiEntityState::Active;
  bool attached = false;
  bool collision_detection = false;
  bool inherit_alpha = false;
  CigiClamp clamp = CigiClamp::None;
  std::uint8_t alpha = 255;
  std::uint16_t type = 0;
  std::uint16_t parent = 0;
  float roll_deg = 0, pitch_deg = 0, yaw_deg = 0;
  glm::dvec3 position{0.0};
  bool operator==(const CigiEntityControl&) const = default;
};

// Articulated Part Control: [2] entity id, [4] part id, [5] bit 0 part
// enabled (shown), bits 1-6 which of x, y, z, roll, pitch, yaw are set;
// [8] x, [12] y, [16] z offsets (m), [20] roll, [24] pitch, [28] yaw (deg),
// f32, relative to the part's place in the model.
struct CigiArticulatedPart {
  std::uint16_t entity = 0;
  std::uint8_t part = 0;
  bool enabled = true;
  std::optional<float> x_m, y_m, z_m, roll_deg, pitch_deg, yaw_deg;
  bool operator==(const CigiArticulatedPart&) const = default;
};

struct CigiEntityPackets {
  std::vector<CigiEntityControl> controls;  // every id, the ownship's (0) included, in datagram order
  std::vector<CigiArticulatedPart> parts;
  std::vector<QueryReject> rejects;  // wrong-size, truncated, non-finite, out-of-range
};

std::array<std::uint8_t, 48> encode_cigi_entity_control(const CigiEntityControl& e, bool swap);
std::array<std::uint8_t, kCigiArticulatedPartControlSize> encode_cigi_articulated_part(const CigiArticulatedPart& a,
                                                                                      bool swap);

}  // namespace ig::io::wire
