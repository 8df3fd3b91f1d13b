#include "io/wire/cigi_views.h"

#include <cmath>

#include "io/wire/byte_io.h"
#include "io/wire/cigi_byte_order.h"
#include "io/wire/cigi.h"
#include "io/wire/cigi_host_datagram.h"
#include "io/wire/cigi_packet_steps.h"

namespace ig::io::wire {

using bytes::Order;

namespace {

// Six f32 at [8], each present when its enable bit is set.
void load_six(const std::uint8_t* p, Order o, std::uint8_t enabled, std::array<std::optional<float>*, 6> out) {
  for (int k = 0; k < 6; ++k)
    if ((enabled >> k) & 1u) *out[std::size_t(k)] = bytes::load_f32(p + 8 + 4 * k, o);
}
void store_six(std::uint8_t* p, Order o, std::array<const std::optional<float>*, 6> in, std::uint8_t& enabled) {
  for (int k = 0; k < 6; ++k) {
    const auto& v = *in[std::size_t(k)];
    if (v) enabled |= std::uint8_t(1u << k);
    bytes::store_f32(p + 8 + 4 * k, v.value_or(0.0f), o);
  }
}

// Both view packets open alike: [0] opcode, [1] size, [2] view, [4] group.
void store_view_head(std::uint8_t* p, std::uint8_t op, std::size_t size, std::uint16_t view, std::uint8_t group,
                     Order o) {
  p[0] = op;
  p[1] = std::uint8_t(size);
  bytes::store_u16(p + 2, view, o);
  p[4] = group;
}

bool finite(const std::optional<float>& v) { return !v || std::isfinite(*v); }
bool within(const std::optional<float>& v, float limit) { return !v || std::abs(*v) <= limit; }

std::optional<QueryReject> check(const CigiViewControl& v) {
  for (const auto* f : {&v.x_m, &v.y_m, &v.z_m, &v.roll_deg, &v.pitch_deg, &v.yaw_deg})
    if (!finite(*f)) return QueryReject::NonFinite;
  for (const auto* f : {&v.x_m, &v.y_m, &v.z_m})
    if (!within(*f, 1e7f)) return QueryReject::OutOfRange;
  for (const auto* f : {&v.roll_deg, &v.pitch_deg, &v.yaw_deg})
    if (!within(*f, 360.0f)) return QueryReject::OutOfRange;
  return std::nullopt;
}

std::optional<QueryReject> check(const CigiViewDefinition& v) {
  for (const auto* f : {&v.near_m, &v.far_m, &v.left_deg, &v.right_deg, &v.top_deg, &v.bottom_deg})
    if (!finite(*f)) return QueryReject::NonFinite;
  for (const auto* f : {&v.left_deg, &v.right_deg, &v.top_deg, &v.bottom_deg})
    if (!within(*f, 90.0f)) return QueryReject::OutOfRange;
  if (v.top_deg && v.bottom_deg && !(*v.top_deg > *v.bottom_deg)) return QueryReject::OutOfRange;
  if (v.left_deg && v.right_deg && !(*v.right_deg > *v.left_deg)) return QueryReject::OutOfRange;
  if ((v.near_m && *v.near_m <= 0.0f) || (v.near_m && v.far_m && !(*v.far_m > *v.near_m)))
    return QueryReject::OutOfRange;
  return std::nullopt;
}

}  // namespace

namespace steps {

bool is_view_op(std::uint8_t op) { return op == kCigiOpViewControl || op == kCigiOpViewDefinition; }

void take_view(std::uint8_t op, const std::uint8_t* q, std::size_t size, Order o, CigiViewPackets& out) {
  if (size != 32) {
    out.rejects.push_back(QueryReject::WrongSize);
    return;
  }
  if (op == kCigiOpViewControl) {
    CigiViewControl v;
    v.view = bytes::load_u16(q + 2, o);
    v.group = q[4];
    v.entity = bytes::load_u16(q + 6, o);
    load_six(q, o, q[5], {&v.x_m, &v.y_m, &v.z_m, &v.roll_deg, &v.pitch_deg, &v.yaw_deg});
    if (const auto bad = check(v)) out.rejects.push_back(*bad);
    else out.controls.push_back(v);
  } else {
    CigiViewDefinition v;
    v.view = bytes::load_u16(q + 2, o);
    v.group = q[4];
    v.mirror = q[5] >> 6;
    v.orthographic = (q[6] >> 3) & 1u;
    load_six(q, o, q[5] & 0x3Fu, {&v.near_m, &v.far_m, &v.left_deg, &v.right_deg, &v.top_deg, &v.bottom_deg});
    if (const auto bad = check(v)) out.rejects.push_back(*bad);
    else out.definitions.push_back(v);
  }
}

}  // namespace steps

CigiViewPackets decode_cigi_view_packets(std::span<const std::uint8_t> data) { return decode_cigi(data).views; }

std::array<std::uint8_t, kCigiViewControlSize> encode_cigi_view_control(const CigiViewControl& v, bool swap) {
  const Order o = cigi_out_order(swap);
  std::array<std::uint8_t, kCigiViewControlSize> b{};
  store_view_head(b.data(), kCigiOpViewControl, b.size(), v.view, v.group, o);
  bytes::store_u16(b.data() + 6, v.entity, o);
  store_six(b.data(), o, {&v.x_m, &v.y_m, &v.z_m, &v.roll_deg, &v.pitch_deg, &v.yaw_deg}, b[5]);
  return b;
}

std::array<std::uint8_t, kCigiViewDefinitionSize> encode_cigi_view_definition(const CigiViewDefinition& v, bool swap) {
  const Order o = cigi_out_order(swap);
  std::array<std::uint8_t, kCigiViewDefinitionSize> b{};
  store_view_head(b.data(), kCigiOpViewDefinition, b.size(), v.view, v.group, o);
  std::uint8_t enabled = 0;
  store_six(b.data(), o, {&v.near_m, &v.far_m, &v.left_deg, &v.right_deg, &v.top_deg, &v.bottom_deg}, enabled);
  b[5] = std::uint8_t(enabled | (v.mirror << 6));
  b[6] = std::uint8_t(v.orthographic ? 1u << 3 : 0u);
  return b;
}

}  // namespace ig::io::wire
