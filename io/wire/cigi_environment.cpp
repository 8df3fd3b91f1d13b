#include "io/wire/cigi_environment.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "io/utc_time.h"
#include "io/wire/byte_io.h"
#include "io/wire/cigi.h"
#include "io/wire/cigi_byte_order.h"
#include "io/wire/cigi_host_datagram.h"
#include "io/wire/cigi_packet_steps.h"
#include "io/wire/cigi_views.h"

namespace ig::io::wire {

using bytes::Order;

namespace {

constexpr double kMaxOffsetM = 1e7;     // entity-relative points: within 10 000 km
constexpr double kMaxRateMps = 1e5;     // as the pose decoders' velocity bound
constexpr double kMaxRateDps = 1e5;     // as the pose decoders' rate bound
constexpr double kMaxVisibilityM = 1e9;  // as the fog's bound (options/shading_options.h)

void load_f32s(const std::uint8_t* p, Order o, std::initializer_list<float*> fields) {
  for (float* f : fields) {
    *f = bytes::load_f32(p, o);
    p += 4;
  }
}
void store_f32s(std::uint8_t* p, Order o, std::initializer_list<float> values) {
  for (float v : values) {
    bytes::store_f32(p, v, o);
    p += 4;
  }
}
glm::dvec3 load_f32_vec(const std::uint8_t* p, Order o) {
  return {bytes::load_f32(p, o), bytes::load_f32(p + 4, o), bytes::load_f32(p + 8, o)};
}
void store_f32_vec(std::uint8_t* p, const glm::dvec3& v, Order o) {
  store_f32s(p, o, {bytes::narrow_f32(v.x), bytes::narrow_f32(v.y), bytes::narrow_f32(v.z)});
}
bool finite(std::initializer_list<double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}
bool within(const glm::dvec3& v, double limit) {
  return std::abs(v.x) <= limit && std::abs(v.y) <= limit && std::abs(v.z) <= limit;
}
std::uint8_t bit(bool on, int k) { return static_cast<std::uint8_t>(on ? 1u << k : 0u); }

template <std::size_t N>
std::array<std::uint8_t, N> packet(std::uint8_t op) {
  std::array<std::uint8_t, N> b{};
  b[0] = op;
  b[1] = std::uint8_t(N);
  return b;
}

using Decoded = std::optional<QueryReject>;  // nullopt: taken

Decoded take_rate(const std::uint8_t* p, Order o, CigiHostPackets& out) {
  CigiRateControl r;
  r.entity = bytes::load_u16(p + 2, o);
  r.part = p[4];
  r.apply_to_part = p[5] & 1u;
  r.body_axes = (p[5] >> 1) & 1u;
  r.velocity_mps = load_f32_vec(p + 8, o);
  r.rates_dps = load_f32_vec(p + 20, o);
  const auto& v = r.velocity_mps;
  const auto& w = r.rates_dps;
  if (!finite({v.x, v.y, v.z, w.x, w.y, w.z})) return QueryReject::NonFinite;
  if (!within(v, kMaxRateMps) || !within(w, kMaxRateDps)) return QueryReject::OutOfRange;
  out.rates.push_back(r);
  return std::nullopt;
}

// Years outside the sun's ephemeris (io/utc_time.h) are refused as well.
bool valid_date(int month, int day, int year) {
  static constexpr int kDays[] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return year >= kMinUtcYear && year <= kMaxUtcYear && month >= 1 && month <= 12 && day >= 1 && day <= kDays[month - 1];
}

Decoded take_celestial(const std::uint8_t* p, Order o, CigiHostPackets& out) {
  CigiCelestialSphere c;
  c.hour = p[2];
  c.minute = p[3];
  c.ephemeris = p[4] & 1u;
  c.sun = (p[4] >> 1) & 1u;
  c.moon = (p[4] >> 2) & 1u;
  c.stars = (p[4] >> 3) & 1u;
  c.date_valid = (p[4] >> 4) & 1u;
  if (c.date_valid) {  // otherwise the date field means nothing
    const std::uint32_t date = bytes::load_u32(p + 8, o);  // MMDDYYYY
    c.month = int(date / 1000000u);
    c.day = int(date / 10000u % 100u);
    c.year = int(date % 10000u);
  }
  c.star_intensity = bytes::load_f32(p + 12, o);
  if (!std::isfinite(c.star_intensity)) return QueryReject::NonFinite;
  if (c.hour > 23 || c.minute > 59 || (c.date_valid && !valid_date(c.month, c.day, c.year)))
    return QueryReject::OutOfRange;
  out.celestial.push_back(c);
  return std::nullopt;
}

Decoded take_atmosphere(const std::uint8_t* p, Order o, CigiHostPackets& out) {
  CigiAtmosphere a;
  a.model_enabled = p[2] & 1u;
  a.humidity_pct = p[3];
  load_f32s(p + 4, o, {&a.air_temp_c, &a.visibility_m, &a.horizontal_wind_mps, &a.vertical_wind_mps,
                       &a.wind_direction_deg, &a.pressure_hpa});
  if (!finite({a.air_temp_c, a.visibility_m, a.horizontal_wind_mps, a.vertical_wind_mps, a.wind_direction_deg,
               a.pressure_hpa}))
    return QueryReject::NonFinite;
  if (a.visibility_m < 0 || a.visibility_m > kMaxVisibilityM) return QueryReject::OutOfRange;
  out.atmosphere.push_back(a);
  return std::nullopt;
}

Decoded take_weather(const std::uint8_t* p, Order o, CigiHostPackets& out) {
  CigiWeatherControl w;
  w.id = bytes::load_u16(p + 2, o);
  w.layer = p[4];
  w.humidity_pct = p[5];
  w.enabled = p[6] & 1u;
  w.cloud_type = p[6] >> 4;
  w.scope = p[7] & 0x3u;
  w.severity = (p[7] >> 2) & 0x7u;
  w.scud = p[6] & 2u;
  load_f32s(p + 8, o, {&w.air_temp_c, &w.visibility_m, &w.scud_frequency_pct, &w.coverage_pct, &w.base_m,
                       &w.thickness_m, &w.transition_band_m, &w.horizontal_wind_mps, &w.vertical_wind_mps,
                       &w.wind_direction_deg});
  if (!finite({w.air_temp_c, w.visibility_m, w.scud_frequency_pct, w.coverage_pct, w.base_m, w.thickness_m,
               w.transition_band_m, w.horizontal_wind_mps, w.vertical_wind_mps, w.wind_direction_deg}))
    return QueryReject::NonFinite;
  if (w.visibility_m < 0 || w.visibility_m > kMaxVisibilityM || w.scope == 3) return QueryReject::OutOfRange;
  out.weather.push_back(w);
  return std::nullopt;
}

Decoded take_segment(const std::uint8_t* p, Order o, CigiHostPackets& out) {
  CigiCollisionSegment s;
  s.entity = bytes::load_u16(p + 2, o);
  s.segment = p[4];
  s.enabled = p[5] & 1u;
  s.start = load_f32_vec(p + 8, o);
  s.end = load_f32_vec(p + 20, o);
  s.material_mask = bytes::load_u32(p + 32, o);
  if (!finite({s.start.x, s.start.y, s.start.z, s.end.x, s.end.y, s.end.z})) return QueryReject::NonFinite;
  if (!within(s.start, kMaxOffsetM) || !within(s.end, kMaxOffsetM)) return QueryReject::OutOfRange;
  out.segments.push_back(s);
  return std::nullopt;
}

Decoded take_position_request(const std::uint8_t* p, Order o, CigiHostPackets& out) {
  CigiPositionRequest r;
  r.of = {bytes::load_u16(p + 2, o), p[4], std::uint8_t((p[5] >> 1) & 0x7u), std::uint8_t((p[5] >> 4) & 0x3u)};
  r.continuous = p[5] & 1u;
  if (r.of.object_class > 4 || r.of.coords > 2) return QueryReject::OutOfRange;
  out.positions.push_back(r);
  return std::nullopt;
}

Decoded take_conditions(const std::uint8_t* p, Order o, CigiHostPackets& out) {
  CigiEnvironmentRequest r;
  r.types = p[2] & 0xFu;
  r.id = p[3];
  r.point = {bytes::load_f64(p + 8, o), bytes::load_f64(p + 16, o), bytes::load_f64(p + 24, o)};
  if (!finite({r.point.x, r.point.y, r.point.z})) return QueryReject::NonFinite;
  if (std::abs(r.point.x) > 90.0 || r.point.y < -180.0 || r.point.y >= 360.0 || std::abs(r.point.z) >= 1e6)
    return QueryReject::OutOfRange;
  out.conditions.push_back(r);
  return std::nullopt;
}

struct HostPacketKind {
  std::uint8_t op;
  std::size_t size;
  Decoded (*take)(const std::uint8_t*, Order, CigiHostPackets&);
};
constexpr HostPacketKind kHostPackets[] = {
    {kCigiOpRateControl, kCigiRateControlSize, take_rate},
    {kCigiOpCelestialSphereControl, kCigiCelestialSphereControlSize, take_celestial},
    {kCigiOpAtmosphereControl, kCigiAtmosphereControlSize, take_atmosphere},
    {kCigiOpWeatherControl, kCigiWeatherControlSize, take_weather},
    {kCigiOpCollisionSegmentDefinition, kCigiCollisionSegmentDefinitionSize, take_segment},
    {kCigiOpPositionRequest, kCigiPositionRequestSize, take_position_request},
    {kCigiOpEnvironmentalConditionsRequest, kCigiEnvironmentalConditionsRequestSize, take_conditions},
};
const HostPacketKind* host_packet_kind(std::uint8_t op) {
  for (const auto& k : kHostPackets)
    if (k.op == op) return &k;
  return nullptr;
}

}  // namespace

namespace steps {

bool is_host_op(std::uint8_t op) { return host_packet_kind(op) != nullptr; }

void take_host(std::uint8_t op, const std::uint8_t* q, std::size_t size, Order o, CigiHostPackets& out) {
  const HostPacketKind* kind = host_packet_kind(op);
  if (size != kind->size) {
    out.rejects.push_back(QueryReject::WrongSize);
    return;
  }
  if (const auto bad = kind->take(q, o, out)) out.rejects.push_back(*bad);
}

}  // namespace steps

bool cigi_opcode_supported(std::uint8_t op) {
  return op == kCigiOpIgControl || steps::is_entity_op(op) || steps::is_view_op(op) || steps::is_request_op(op) ||
         steps::is_host_op(op);
}

CigiHostPackets decode_cigi_host_packets(std::span<const std::uint8_t> data) { return decode_cigi(data).host; }

std::array<std::uint8_t, kCigiRateControlSize> encode_cigi_rate_control(const CigiRateControl& r, bool swap) {
  const Order o = cigi_out_order(swap);
  auto b = packet<kCigiRateControlSize>(kCigiOpRateControl);
  bytes::store_u16(b.data() + 2, r.entity, o);
  b[4] = r.part;
  b[5] = bit(r.apply_to_part, 0) | bit(r.body_axes, 1);
  store_f32_vec(b.data() + 8, r.velocity_mps, o);
  store_f32_vec(b.data() + 20, r.rates_dps, o);
  return b;
}

std::array<std::uint8_t, kCigiCelestialSphereControlSize> encode_cigi_celestial(const CigiCelestialSphere& c,
                                                                                bool swap) {
  const Order o = cigi_out_order(swap);
  auto b = packet<kCigiCelestialSphereControlSize>(kCigiOpCelestialSphereControl);
  b[2] = c.hour;
  b[3] = c.minute;
  b[4] = bit(c.ephemeris, 0) | bit(c.sun, 1) | bit(c.moon, 2) | bit(c.stars, 3) | bit(c.date_valid, 4);
  bytes::store_u32(b.data() + 8, std::uint32_t(c.month) * 1000000u + std::uint32_t(c.day) * 10000u + std::uint32_t(c.year), o);
  bytes::store_f32(b.data() + 12, c.star_intensity, o);
  return b;
}

std::array<std::uint8_t, kCigiAtmosphereControlSize> encode_cigi_atmosphere(const CigiAtmosphere& a, bool swap) {
  const Order o = cigi_out_order(swap);
  auto b = packet<kCigiAtmosphereControlSize>(kCigiOpAtmosphereControl);
  b[2] = bit(a.model_enabled, 0);
  b[3] = a.humidity_pct;
  store_f32s(b.data() + 4, o, {a.air_temp_c, a.visibility_m, a.horizontal_wind_mps, a.vertical_wind_mps,
                               a.wind_direction_deg, a.pressure_hpa});
  return b;
}

std::array<std::uint8_t, kCigiWeatherControlSize> encode_cigi_weather(const CigiWeatherControl& w, bool swap) {
  const Order o = cigi_out_order(swap);
  auto b = packet<kCigiWeatherControlSize>(kCigiOpWeatherControl);
  bytes::store_u16(b.data() + 2, w.id, o);
  b[4] = w.layer;
  b[5] = w.humidity_pct;
  b[6] = std::uint8_t(bit(w.enabled, 0) | bit(w.scud, 1) | (w.cloud_type << 4));
  b[7] = std::uint8_t((w.scope & 0x3u) | ((w.severity & 0x7u) << 2));
  store_f32s(b.data() + 8, o, {w.air_temp_c, w.visibility_m, w.scud_frequency_pct, w.coverage_pct, w.base_m,
                               w.thickness_m, w.transition_band_m, w.horizontal_wind_mps, w.vertical_wind_mps,
                               w.wind_direction_deg});
  return b;
}

std::optional<options::CloudLayer> cigi_cloud_layer(const CigiWeatherControl& w) {
  const auto type = options::cloud_type_of_cigi(w.cloud_type);
  if (!type) return std::nullopt;
  options::CloudLayer l;
  l.id = w.layer;
  l.type = *type;
  l.coverage = double(w.coverage_pct) / 100.0;
  l.base_m = w.base_m;
  l.thickness_m = w.thickness_m;
  l.transition_m = w.transition_band_m;
  l.visibility_m = w.visibility_m;
  l.scud = w.scud ? double(w.scud_frequency_pct) / 100.0 : 0.0;
  l.wind_mps = options::wind_from(w.horizontal_wind_mps, w.wind_direction_deg);
  return l;
}

std::array<std::uint8_t, kCigiCollisionSegmentDefinitionSize> encode_cigi_collision_segment(
    const CigiCollisionSegment& s, bool swap) {
  const Order o = cigi_out_order(swap);
  auto b = packet<kCigiCollisionSegmentDefinitionSize>(kCigiOpCollisionSegmentDefinition);
  bytes::store_u16(b.data() + 2, s.entity, o);
  b[4] = s.segment;
  b[5] = bit(s.enabled, 0);
  store_f32_vec(b.data() + 8, s.start, o);
  store_f32_vec(b.data() + 20, s.end, o);
  bytes::store_u32(b.data() + 32, s.material_mask, o);
  return b;
}

std::array<std::uint8_t, kCigiPositionRequestSize> encode_cigi_position_request(const CigiPositionRequest& r,
                                                                                bool swap) {
  const Order o = cigi_out_order(swap);
  auto b = packet<kCigiPositionRequestSize>(kCigiOpPositionRequest);
  bytes::store_u16(b.data() + 2, r.of.object, o);
  b[4] = r.of.part;
  b[5] = std::uint8_t(bit(r.continuous, 0) | ((r.of.object_class & 0x7u) << 1) | ((r.of.coords & 0x3u) << 4));
  return b;
}

std::array<std::uint8_t, kCigiEnvironmentalConditionsRequestSize> encode_cigi_environment_request(
    const CigiEnvironmentRequest& r, bool swap) {
  const Order o = cigi_out_order(swap);
  auto b = packet<kCigiEnvironmentalConditionsRequestSize>(kCigiOpEnvironmentalConditionsRequest);
  b[2] = r.types & 0xFu;
  b[3] = r.id;
  bytes::store_f64(b.data() + 8, r.point.x, o);
  bytes::store_f64(b.data() + 16, r.point.y, o);
  bytes::store_f64(b.data() + 24, r.point.z, o);
  return b;
}

}  // namespace ig::io::wire
