#include "io/wire/cigi_entities.h"

#include <cmath>

#include "io/wire/byte_io.h"
#include "io/wire/cigi.h"
#include "io/wire/cigi_byte_order.h"
#include "io/wire/cigi_packet_steps.h"

namespace ig::io::wire {

using bytes::Order;

namespace {

constexpr double kMaxOffsetM = 1e7;      // attached offsets: within 10 000 km, as query offsets
constexpr float kMaxAngleDeg = 1.0e4f;   // as the pose decoders' bound
constexpr float kMaxPartOffsetM = 1.0e4f;  // a part moves within 10 km of its place in the model

bool finite_angles(const CigiEntityControl& e) {
  return std::isfinite(e.roll_deg) && std::isfinite(e.pitch_deg) && std::isfinite(e.yaw_deg);
}

std::optional<QueryReject> check(const CigiEntityControl& e) {
  const glm::dvec3& p = e.position;
  if (!finite_angles(e) || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    return QueryReject::NonFinite;
  if (std::abs(e.roll_deg) > kMaxAngleDeg || std::abs(e.pitch_deg) > kMaxAngleDeg || std::abs(e.yaw_deg) > kMaxAngleDeg)
    return QueryReject::OutOfRange;
  if (e.attached) {
    if (std::abs(p.x) > kMaxOffsetM || std::abs(p.y) > kMaxOffsetM || std::abs(p.z) > kMaxOffsetM)
      return QueryReject::OutOfRange;
  } else if (p.x < -90.0 || p.x > 90.0 || p.y < -180.0 || p.y >= 360.0 || std::abs(p.z) > kMaxAbsAltitude) {
    return QueryReject::OutOfRange;
  }
  return std::nullopt;
}

std::optional<QueryReject> take_entity_control(const std::uint8_t* p, Order o, CigiEntityPackets& out) {
  CigiEntityControl e;
  e.entity = bytes::load_u16(p + 2, o);
  const std::uint8_t state = p[4] & 0x3u, clamp = (p[4] >> 5) & 0x3u;
  if (state == 3 || clamp == 3) return QueryReject::OutOfRange;
  e.state = CigiEntityState(state);
  e.attached = (p[4] >> 2) & 1u;
  e.collision_detection = (p[4] >> 3) & 1u;
  e.inherit_alpha = (p[4] >> 4) & 1u;
  e.clamp = CigiClamp(clamp);
  e.alpha = p[6];
  e.type = bytes::load_u16(p + 8, o);
  e.parent = bytes::load_u16(p + 10, o);
  e.roll_deg = bytes::load_f32(p + 12, o);
  e.pitch_deg = bytes::load_f32(p + 16, o);
  e.yaw_deg = bytes::load_f32(p + 20, o);
  e.position = {bytes::load_f64(p + 24, o), bytes::load_f64(p + 32, o), bytes::load_f64(p + 40, o)};
  if (const auto bad = check(e)) return bad;
  out.controls.push_back(e);
  return std::nullopt;
}

std::optional<QueryReject> take_articulated_part(const std::uint8_t* p, Order o, CigiEntityPackets& out) {
  CigiArticulatedPart a;
  a.entity = bytes::load_u16(p + 2, o);
  a.part = p[4];
  a.enabled = p[5] & 1u;
  std::optional<float>* fields[] = {&a.x_m, &a.y_m, &a.z_m, &a.roll_deg, &a.pitch_deg, &a.yaw_deg};
  for (int k = 0; k < 6; ++k) {
    if (!((p[5] >> (k + 1)) & 1u)) continue;
    const float v = bytes::load_f32(p + 8 + 4 * k, o);
    if (!std::isfinite(v)) return QueryReject::NonFinite;
    if (std::abs(v) > (k < 3 ? kMaxPartOffsetM : kMaxAngleDeg)) return QueryReject::OutOfRange;
    *fields[k] = v;
  }
  out.parts.push_back(a);
  return std::nullopt;
}

}  // namespace

namespace steps {

bool is_entity_op(std::uint8_t op) { return op == kCigiOpEntityControl || op == kCigiOpArticulatedPartControl; }

void take_entity(std::uint8_t op, const std::uint8_t* p, std::size_t size, Order o, CigiEntityPackets& out) {
  const bool control = op == kCigiOpEntityControl;
  if (size != (control ? kCigiEntityControlSize : kCigiArticulatedPartControlSize)) {
    out.rejects.push_back(QueryReject::WrongSize);
    return;
  }
  if (const auto bad = control ? take_entity_control(p, o, out) : take_articulated_part(p, o, out))
    out.rejects.push_back(*bad);
}

}  // namespace steps

std::array<std::uint8_t, 48> encode_cigi_entity_control(const CigiEntityControl& e, bool swap) {
  const Order o = cigi_out_order(swap);
  std::array<std::uint8_t, 48> b{};
  b[0] = kCigiOpEntityControl;
  b[1] = std::uint8_t(b.size());
  bytes::store_u16(b.data() + 2, e.entity, o);
  b[4] = std::uint8_t((std::uint8_t(e.state) & 0x3u) | (e.attached ? 1u << 2 : 0u) |
                      (e.collision_detection ? 1u << 3 : 0u) | (e.inherit_alpha ? 1u << 4 : 0u) |
                      ((std::uint8_t(e.clamp) & 0x3u) << 5));
  b[6] = e.alpha;
  bytes::store_u16(b.data() + 8, e.type, o);
  bytes::store_u16(b.data() + 10, e.parent, o);
  bytes::store_f32(b.data() + 12, e.roll_deg, o);
  bytes::store_f32(b.data() + 16, e.pitch_deg, o);
  bytes::store_f32(b.data() + 20, e.yaw_deg, o);
  bytes::store_f64(b.data() + 24, e.position.x, o);
  bytes::store_f64(b.data() + 32, e.position.y, o);
  bytes::store_f64(b.data() + 40, e.position.z, o);
  return b;
}

std::array<std::uint8_t, kCigiArticulatedPartControlSize> encode_cigi_articulated_part(const CigiArticulatedPart& a,
                                                                                      bool swap) {
  const Order o = cigi_out_order(swap);
  std::array<std::uint8_t, kCigiArticulatedPartControlSize> b{};
  b[0] = kCigiOpArticulatedPartControl;
  b[1] = std::uint8_t(b.size());
  bytes::store_u16(b.data() + 2, a.entity, o);
  b[4] = a.part;
  b[5] = a.enabled ? 1u : 0u;
  const std::optional<float>* fields[] = {&a.x_m, &a.y_m, &a.z_m, &a.roll_deg, &a.pitch_deg, &a.yaw_deg};
  for (int k = 0; k < 6; ++k) {
    if (*fields[k]) b[5] = std::uint8_t(b[5] | (1u << (k + 1)));
    bytes::store_f32(b.data() + 8 + 4 * k, fields[k]->value_or(0.0f), o);
  }
  return b;
}

}  // namespace ig::io::wire
