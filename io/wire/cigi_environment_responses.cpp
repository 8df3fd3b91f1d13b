// The IG -> host half of cigi_environment.h: Position Response, Collision
// Detection Segment Notification, Weather Conditions Response, IG Message.
#include <algorithm>
#include <cstring>

#include "io/wire/byte_io.h"
#include "io/wire/cigi.h"
#include "io/wire/cigi_byte_order.h"
#include "io/wire/cigi_environment.h"

namespace ig::io::wire {

using bytes::Order;

namespace {

std::uint8_t* grow(std::vector<std::uint8_t>& out, std::uint8_t op, std::size_t size) {
  const std::size_t at = out.size();
  out.resize(at + size, 0);
  out[at] = op;
  out[at + 1] = std::uint8_t(size);
  return out.data() + at;
}

}  // namespace

void append_cigi_position_response(const CigiPositionResponse& r, bool swap, std::vector<std::uint8_t>& out) {
  const Order o = cigi_out_order(swap);
  std::uint8_t* b = grow(out, kCigiOpPositionResponse, kCigiPositionResponseSize);
  bytes::store_u16(b + 2, r.of.object, o);
  b[4] = r.of.part;
  b[5] = std::uint8_t((r.of.object_class & 0x7u) | ((r.of.coords & 0x3u) << 3));
  bytes::store_f64(b + 8, r.position.x, o);
  bytes::store_f64(b + 16, r.position.y, o);
  bytes::store_f64(b + 24, r.position.z, o);
  bytes::store_f32(b + 32, r.roll_deg, o);
  bytes::store_f32(b + 36, r.pitch_deg, o);
  bytes::store_f32(b + 40, r.yaw_deg, o);
}

void append_cigi_collision_notification(const CigiCollisionNotification& n, bool swap,
                                        std::vector<std::uint8_t>& out) {
  const Order o = cigi_out_order(swap);
  std::uint8_t* b = grow(out, kCigiOpCollisionSegmentNotification, kCigiCollisionSegmentNotificationSize);
  bytes::store_u16(b + 2, n.entity, o);
  b[4] = n.segment;
  b[5] = n.with_entity ? 1u : 0u;
  bytes::store_u16(b + 6, n.contacted_entity, o);
  bytes::store_u32(b + 8, n.material, o);
  bytes::store_f32(b + 12, n.distance_m, o);
}

void append_cigi_weather_conditions(const CigiWeatherConditions& w, bool swap, std::vector<std::uint8_t>& out) {
  const Order o = cigi_out_order(swap);
  std::uint8_t* b = grow(out, kCigiOpWeatherConditionsResponse, kCigiWeatherConditionsResponseSize);
  b[2] = w.request_id;
  b[3] = w.humidity_pct;
  const float values[] = {w.air_temp_c,        w.visibility_m,       w.horizontal_wind_mps,
                          w.vertical_wind_mps, w.wind_direction_deg, w.pressure_hpa};
  for (std::size_t k = 0; k < std::size(values); ++k) bytes::store_f32(b + 4 + 4 * k, values[k], o);
}

void append_cigi_ig_message(const CigiIgMessage& m, bool swap, std::vector<std::uint8_t>& out) {
  // Text and its NUL after the 4-byte head, padded to a multiple of 8.
  const std::size_t text = std::min(m.text.size(), kCigiIgMessageMaxSize - 5);
  const std::size_t size = std::min(kCigiIgMessageMaxSize, (4 + text + 1 + 7) / 8 * 8);
  std::uint8_t* b = grow(out, kCigiOpIgMessage, size);
  bytes::store_u16(b + 2, m.id, cigi_out_order(swap));
  std::memcpy(b + 4, m.text.data(), text);
}

std::optional<CigiIgPackets> decode_cigi_ig_packets(std::span<const std::uint8_t> data) {
  const auto sof = decode_cigi_start_of_frame(data);
  if (!sof.sof) return std::nullopt;
  const Order o = sof.sof->byte_swapped ? bytes::swapped(bytes::kHostOrder) : bytes::kHostOrder;
  CigiIgPackets out;
  const bool framed = for_each_cigi_ig_packet(data, kCigiStartOfFrameSize, [&](std::uint8_t op, const std::uint8_t* q,
                                                                               std::size_t size) {
    if (op == kCigiOpPositionResponse && size == kCigiPositionResponseSize) {
      CigiPositionResponse r;
      r.of = {bytes::load_u16(q + 2, o), q[4], std::uint8_t(q[5] & 0x7u), std::uint8_t((q[5] >> 3) & 0x3u)};
      r.position = {bytes::load_f64(q + 8, o), bytes::load_f64(q + 16, o), bytes::load_f64(q + 24, o)};
      r.roll_deg = bytes::load_f32(q + 32, o);
      r.pitch_deg = bytes::load_f32(q + 36, o);
      r.yaw_deg = bytes::load_f32(q + 40, o);
      out.positions.push_back(r);
    } else if (op == kCigiOpCollisionSegmentNotification && size == kCigiCollisionSegmentNotificationSize) {
      CigiCollisionNotification n;
      n.entity = bytes::load_u16(q + 2, o);
      n.segment = q[4];
      n.with_entity = q[5] & 1u;
      n.contacted_entity = bytes::load_u16(q + 6, o);
      n.material = bytes::load_u32(q + 8, o);
      n.distance_m = bytes::load_f32(q + 12, o);
      out.collisions.push_back(n);
    } else if (op == kCigiOpWeatherConditionsResponse && size == kCigiWeatherConditionsResponseSize) {
      CigiWeatherConditions w;
      w.request_id = q[2];
      w.humidity_pct = q[3];
      float* fields[] = {&w.air_temp_c,        &w.visibility_m,       &w.horizontal_wind_mps,
                         &w.vertical_wind_mps, &w.wind_direction_deg, &w.pressure_hpa};
      for (std::size_t k = 0; k < std::size(fields); ++k) *fields[k] = bytes::load_f32(q + 4 + 4 * k, o);
      out.weather.push_back(w);
    } else if (op == kCigiOpIgMessage && size >= 5) {
      const char* text = reinterpret_cast<const char*>(q + 4);
      out.messages.push_back({bytes::load_u16(q + 2, o), std::string(text, strnlen(text, size - 4))});
    }
  });
  if (!framed) return std::nullopt;
  return out;
}

}  // namespace ig::io::wire
