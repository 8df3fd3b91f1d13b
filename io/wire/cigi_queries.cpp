#include "io/wire/cigi_queries.h"

#include <cmath>
#include <type_traits>

#include "io/wire/byte_io.h"
#include "io/wire/cigi_byte_order.h"
#include "io/wire/cigi.h"
#include "io/wire/cigi_host_datagram.h"
#include "io/wire/cigi_packet_steps.h"

namespace ig::io::wire {

using bytes::Order;

namespace {

// Offsets from an entity, metres: anything within 10 000 km.
constexpr double kMaxOffsetM = 1e7;

bool finite3(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A point in its coordinate system: geodetic as the pose decoders accept
// (pose_message.h), entity offsets bounded.
std::optional<QueryReject> check_point(const glm::dvec3& p, CigiCoords c) {
  if (!finite3(p)) return QueryReject::NonFinite;
  if (c == CigiCoords::Geodetic) {
    if (p.x < -90.0 || p.x > 90.0 || p.y < -180.0 || p.y >= 360.0 || std::abs(p.z) >= 1e6)
      return QueryReject::OutOfRange;
  } else if (std::abs(p.x) > kMaxOffsetM || std::abs(p.y) > kMaxOffsetM || std::abs(p.z) > kMaxOffsetM) {
    return QueryReject::OutOfRange;
  }
  return std::nullopt;
}

glm::dvec3 load_point(const std::uint8_t* p, Order o) {
  return {bytes::load_f64(p, o), bytes::load_f64(p + 8, o), bytes::load_f64(p + 16, o)};
}
void store_point(std::uint8_t* p, const glm::dvec3& v, Order o) {
  bytes::store_f64(p, v.x, o);
  bytes::store_f64(p + 8, v.y, o);
  bytes::store_f64(p + 16, v.z, o);
}
CigiCoords coords_bit(std::uint8_t flags, int bit) {
  return (flags >> bit) & 1u ? CigiCoords::Entity : CigiCoords::Geodetic;
}

// HAT/HOT Request: [2] id, [4] bits 0-1 type, bit 2 coordinate system,
// [5] update period, [6] entity, [8] lat / x, [16] lon / y, [24] alt / z.
std::variant<HatHotRequest, QueryReject> decode_hat_hot(const std::uint8_t* p, Order o) {
  HatHotRequest r;
  r.id = bytes::load_u16(p + 2, o);
  if ((p[4] & 0x3u) == 3) return QueryReject::BadType;
  r.type = HatHotType(p[4] & 0x3u);
  r.coords = coords_bit(p[4], 2);
  r.update_period = p[5];
  r.entity = bytes::load_u16(p + 6, o);
  r.point = load_point(p + 8, o);
  if (const auto bad = check_point(r.point, r.coords)) return *bad;
  return r;
}

// Both LOS requests open alike: [2] id, [4] bit 0 extended, bit 1 source
// coordinates, [5] alpha threshold, [6] entity; the rest of [4] differs.
template <class LosRequest>
LosRequest load_los_head(const std::uint8_t* p, Order o) {
  LosRequest r;
  r.id = bytes::load_u16(p + 2, o);
  r.extended = p[4] & 1u;
  r.source_coords = coords_bit(p[4], 1);
  r.alpha_threshold = p[5];
  r.entity = bytes::load_u16(p + 6, o);
  return r;
}

// LOS Segment Request: [2] id, [4] bit 0 extended, 1 source coords,
// 2 destination coords, 3 response coords, 4 destination entity valid;
// [5] alpha threshold, [6] entity, [8] source (3 x f64), [32] destination,
// [56] material mask, [60] update period, [62] destination entity.
std::variant<LosSegmentRequest, QueryReject> decode_los_segment(const std::uint8_t* p, Order o) {
  auto r = load_los_head<LosSegmentRequest>(p, o);
  r.destination_coords = coords_bit(p[4], 2);
  r.response_coords = coords_bit(p[4], 3);
  r.destination_entity_valid = (p[4] >> 4) & 1u;
  r.source = load_point(p + 8, o);
  r.destination = load_point(p + 32, o);
  r.material_mask = bytes::load_u32(p + 56, o);
  r.update_period = p[60];
  r.destination_entity = bytes::load_u16(p + 62, o);
  if (const auto bad = check_point(r.source, r.source_coords)) return *bad;
  if (const auto bad = check_point(r.destination, r.destination_coords)) return *bad;
  return r;
}

// LOS Vector Request: [2] id, [4] bit 0 extended, 1 source coords,
// 2 response coords; [5] alpha, [6] entity, [8] azimuth f32, [12] elevation,
// [16] min range, [20] max range, [24] source (3 x f64), [48] material mask,
// [52] update period.
std::variant<LosVectorRequest, QueryReject> decode_los_vector(const std::uint8_t* p, Order o) {
  auto r = load_los_head<LosVectorRequest>(p, o);
  r.response_coords = coords_bit(p[4], 2);
  r.azimuth_deg = bytes::load_f32(p + 8, o);
  r.elevation_deg = bytes::load_f32(p + 12, o);
  r.min_range_m = bytes::load_f32(p + 16, o);
  r.max_range_m = bytes::load_f32(p + 20, o);
  r.source = load_point(p + 24, o);
  r.material_mask = bytes::load_u32(p + 48, o);
  r.update_period = p[52];
  if (!std::isfinite(r.azimuth_deg) || !std::isfinite(r.elevation_deg) || !std::isfinite(r.min_range_m) ||
      !std::isfinite(r.max_range_m))
    return QueryReject::NonFinite;
  if (std::abs(r.azimuth_deg) > 360.0f || std::abs(r.elevation_deg) > 90.0f || r.min_range_m < 0.0f ||
      r.max_range_m < r.min_range_m)
    return QueryReject::OutOfRange;
  if (const auto bad = check_point(r.source, r.source_coords)) return *bad;
  return r;
}

std::size_t request_size(std::uint8_t op) {
  switch (op) {
    case kCigiOpHatHotRequest: return kCigiHatHotRequestSize;
    case kCigiOpLosSegmentRequest: return kCigiLosSegmentRequestSize;
    case kCigiOpLosVectorRequest: return kCigiLosVectorRequestSize;
  }
  return 0;
}

void header(std::uint8_t* p, std::uint8_t op, std::size_t size, std::uint16_t id, Order o) {
  p[0] = op;
  p[1] = static_cast<std::uint8_t>(size);
  bytes::store_u16(p + 2, id, o);
}

std::uint8_t lsn(std::uint32_t host_frame) { return static_cast<std::uint8_t>((host_frame & 0xFu) << 4); }

// The head load_los_head reads; the caller adds its own bits of [4].
template <class LosRequest>
void store_los_head(std::uint8_t* p, std::uint8_t op, std::size_t size, const LosRequest& r, Order o) {
  header(p, op, size, r.id, o);
  p[4] = static_cast<std::uint8_t>(std::uint8_t(r.extended) | (std::uint8_t(r.source_coords) << 1));
  p[5] = r.alpha_threshold;
  bytes::store_u16(p + 6, r.entity, o);
}

}  // namespace

std::uint16_t request_id(const CigiRequest& r) {
  return std::visit([](const auto& q) { return q.id; }, r);
}
std::uint8_t update_period(const CigiRequest& r) {
  return std::visit([](const auto& q) { return q.update_period; }, r);
}

const char* query_reject_name(QueryReject r) {
  switch (r) {
    case QueryReject::WrongSize: return "wrong-size";
    case QueryReject::Truncated: return "truncated";
    case QueryReject::BadType: return "bad-type";
    case QueryReject::NonFinite: return "non-finite";
    case QueryReject::OutOfRange: return "out-of-range";
  }
  return "unknown";
}

namespace steps {

bool is_request_op(std::uint8_t op) { return request_size(op) != 0; }

void take_request(std::uint8_t op, const std::uint8_t* q, std::size_t size, Order o, const CigiRequestLimits& limits,
                  CigiRequests& out) {
  if (size != request_size(op)) {
    out.rejects.push_back(QueryReject::WrongSize);
    return;
  }
  auto take = [&](auto decoded) {
    if (const auto* bad = std::get_if<QueryReject>(&decoded)) {
      out.rejects.push_back(*bad);
    } else if (out.requests.size() >= limits.max_requests) {
      ++out.overflow;
    } else {
      std::visit([&](const auto& r) {
        if constexpr (!std::is_same_v<std::decay_t<decltype(r)>, QueryReject>) out.requests.emplace_back(r);
      }, decoded);
    }
  };
  if (op == kCigiOpHatHotRequest) take(decode_hat_hot(q, o));
  else if (op == kCigiOpLosSegmentRequest) take(decode_los_segment(q, o));
  else take(decode_los_vector(q, o));
}

}  // namespace steps

CigiRequests decode_cigi_requests(std::span<const std::uint8_t> data, const CigiRequestLimits& limits) {
  return decode_cigi(data, limits).requests;
}

std::array<std::uint8_t, kCigiHatHotRequestSize> encode_cigi_hat_hot_request(const HatHotRequest& r, bool swap) {
  const Order o = cigi_out_order(swap);
  std::array<std::uint8_t, kCigiHatHotRequestSize> b{};
  header(b.data(), kCigiOpHatHotRequest, b.size(), r.id, o);
  b[4] = static_cast<std::uint8_t>((std::uint8_t(r.type) & 0x3u) | (std::uint8_t(r.coords) << 2));
  b[5] = r.update_period;
  bytes::store_u16(b.data() + 6, r.entity, o);
  store_point(b.data() + 8, r.point, o);
  return b;
}

std::array<std::uint8_t, kCigiLosSegmentRequestSize> encode_cigi_los_segment_request(const LosSegmentRequest& r,
                                                                                     bool swap) {
  const Order o = cigi_out_order(swap);
  std::array<std::uint8_t, kCigiLosSegmentRequestSize> b{};
  store_los_head(b.data(), kCigiOpLosSegmentRequest, b.size(), r, o);
  b[4] |= static_cast<std::uint8_t>((std::uint8_t(r.destination_coords) << 2) |
                                    (std::uint8_t(r.response_coords) << 3) |
                                    (std::uint8_t(r.destination_entity_valid) << 4));
  store_point(b.data() + 8, r.source, o);
  store_point(b.data() + 32, r.destination, o);
  bytes::store_u32(b.data() + 56, r.material_mask, o);
  b[60] = r.update_period;
  bytes::store_u16(b.data() + 62, r.destination_entity, o);
  return b;
}

std::array<std::uint8_t, kCigiLosVectorRequestSize> encode_cigi_los_vector_request(const LosVectorRequest& r,
                                                                                   bool swap) {
  const Order o = cigi_out_order(swap);
  std::array<std::uint8_t, kCigiLosVectorRequestSize> b{};
  store_los_head(b.data(), kCigiOpLosVectorRequest, b.size(), r, o);
  b[4] |= static_cast<std::uint8_t>(std::uint8_t(r.response_coords) << 2);
  bytes::store_f32(b.data() + 8, r.azimuth_deg, o);
  bytes::store_f32(b.data() + 12, r.elevation_deg, o);
  bytes::store_f32(b.data() + 16, r.min_range_m, o);
  bytes::store_f32(b.data() + 20, r.max_range_m, o);
  store_point(b.data() + 24, r.source, o);
  bytes::store_u32(b.data() + 48, r.material_mask, o);
  b[52] = r.update_period;
  return b;
}

std::size_t cigi_response_size(const CigiResponse& r) {
  if (const auto* h = std::get_if<HatHotResponse>(&r))
    return h->extended ? kCigiHatHotExtendedResponseSize : kCigiHatHotResponseSize;
  return std::get<LosResponse>(r).extended ? kCigiLosExtendedResponseSize : kCigiLosResponseSize;
}

void append_cigi_response(const CigiResponse& resp, bool swap, std::vector<std::uint8_t>& out) {
  const Order o = cigi_out_order(swap);
  const std::size_t at = out.size(), size = cigi_response_size(resp);
  out.resize(at + size, 0);
  std::uint8_t* p = out.data() + at;
  if (const auto* h = std::get_if<HatHotResponse>(&resp)) {
    // [4] bit 0 valid, bit 1 response type (basic only), bits 4-7 host frame LSN.
    if (!h->extended) {
      header(p, kCigiOpHatHotResponse, size, h->id, o);
      p[4] = static_cast<std::uint8_t>(std::uint8_t(h->valid) | ((h->type == HatHotType::Hot ? 1u : 0u) << 1) |
                                       lsn(h->host_frame));
      bytes::store_f64(p + 8, h->valid ? (h->type == HatHotType::Hot ? h->hot_m : h->hat_m) : 0.0, o);
      return;
    }
    header(p, kCigiOpHatHotExtendedResponse, size, h->id, o);
    p[4] = static_cast<std::uint8_t>(std::uint8_t(h->valid) | lsn(h->host_frame));
    bytes::store_f64(p + 8, h->valid ? h->hat_m : 0.0, o);
    bytes::store_f64(p + 16, h->valid ? h->hot_m : 0.0, o);
    bytes::store_u32(p + 24, h->material, o);
    bytes::store_f32(p + 28, h->valid ? h->normal_azimuth_deg : 0.0f, o);
    bytes::store_f32(p + 32, h->valid ? h->normal_elevation_deg : 0.0f, o);
    return;
  }
  const LosResponse& l = std::get<LosResponse>(resp);
  if (!l.extended) {
    // [4] bit 0 valid, 1 entity id valid, 2 visible, 4-7 host frame LSN;
    // [5] response count, [6] entity, [8] range.
    header(p, kCigiOpLosResponse, size, l.id, o);
    p[4] = static_cast<std::uint8_t>(std::uint8_t(l.valid) | (std::uint8_t(l.entity_valid) << 1) |
                                     (std::uint8_t(l.visible) << 2) | lsn(l.host_frame));
    p[5] = l.response_count;
    bytes::store_u16(p + 6, l.entity, o);
    bytes::store_f64(p + 8, l.range_m, o);
    return;
  }
  // [4] bit 0 valid, 1 entity id valid, 2 range valid, 3 visible, 4-7 LSN;
  // [5] count, [6] entity, [8] range, [16] point (3 x f64), [40] RGBA,
  // [44] material, [48] normal azimuth, [52] normal elevation.
  header(p, kCigiOpLosExtendedResponse, size, l.id, o);
  p[4] = static_cast<std::uint8_t>(std::uint8_t(l.valid) | (std::uint8_t(l.entity_valid) << 1) |
                                   (std::uint8_t(l.range_valid) << 2) | (std::uint8_t(l.visible) << 3) |
                                   lsn(l.host_frame));
  p[5] = l.response_count;
  bytes::store_u16(p + 6, l.entity, o);
  bytes::store_f64(p + 8, l.range_m, o);
  store_point(p + 16, l.point, o);
  for (int k = 0; k < 4; ++k) p[40 + k] = l.rgba[std::size_t(k)];
  bytes::store_u32(p + 44, l.material, o);
  bytes::store_f32(p + 48, l.normal_azimuth_deg, o);
  bytes::store_f32(p + 52, l.normal_elevation_deg, o);
}

std::optional<std::vector<CigiResponse>> decode_cigi_responses(std::span<const std::uint8_t> data) {
  const auto sof = decode_cigi_start_of_frame(data);
  if (!sof.sof) return std::nullopt;
  const Order o = sof.sof->byte_swapped ? bytes::swapped(bytes::kHostOrder) : bytes::kHostOrder;
  std::vector<CigiResponse> out;
  const bool framed = for_each_cigi_ig_packet(data, kCigiStartOfFrameSize, [&](std::uint8_t op, const std::uint8_t* q,
                                                                               std::size_t size) {
    const std::uint32_t frame = size > 4 ? std::uint32_t(q[4] >> 4) : 0u;  // only read inside the packet
    if (op == kCigiOpHatHotResponse && size == kCigiHatHotResponseSize) {
      HatHotResponse h;
      h.id = bytes::load_u16(q + 2, o);
      h.valid = q[4] & 1u;
      h.type = (q[4] >> 1) & 1u ? HatHotType::Hot : HatHotType::Hat;
      h.host_frame = frame;
      (h.type == HatHotType::Hot ? h.hot_m : h.hat_m) = bytes::load_f64(q + 8, o);
      out.emplace_back(h);
    } else if (op == kCigiOpHatHotExtendedResponse && size == kCigiHatHotExtendedResponseSize) {
      HatHotResponse h;
      h.extended = true;
      h.type = HatHotType::Extended;
      h.id = bytes::load_u16(q + 2, o);
      h.valid = q[4] & 1u;
      h.host_frame = frame;
      h.hat_m = bytes::load_f64(q + 8, o);
      h.hot_m = bytes::load_f64(q + 16, o);
      h.material = bytes::load_u32(q + 24, o);
      h.normal_azimuth_deg = bytes::load_f32(q + 28, o);
      h.normal_elevation_deg = bytes::load_f32(q + 32, o);
      out.emplace_back(h);
    } else if ((op == kCigiOpLosResponse && size == kCigiLosResponseSize) ||
               (op == kCigiOpLosExtendedResponse && size == kCigiLosExtendedResponseSize)) {
      LosResponse l;
      l.extended = op == kCigiOpLosExtendedResponse;
      l.id = bytes::load_u16(q + 2, o);
      l.valid = q[4] & 1u;
      l.entity_valid = (q[4] >> 1) & 1u;
      l.host_frame = frame;
      l.response_count = q[5];
      l.entity = bytes::load_u16(q + 6, o);
      l.range_m = bytes::load_f64(q + 8, o);
      if (!l.extended) {
        l.visible = (q[4] >> 2) & 1u;
        l.range_valid = l.valid && !l.visible;
      } else {
        l.range_valid = (q[4] >> 2) & 1u;
        l.visible = (q[4] >> 3) & 1u;
        l.point = load_point(q + 16, o);
        for (int k = 0; k < 4; ++k) l.rgba[std::size_t(k)] = q[40 + k];
        l.material = bytes::load_u32(q + 44, o);
        l.normal_azimuth_deg = bytes::load_f32(q + 48, o);
        l.normal_elevation_deg = bytes::load_f32(q + 52, o);
      }
      out.emplace_back(l);
    }
  });
  if (!framed) return std::nullopt;
  return out;
}

}  // namespace ig::io::wire
