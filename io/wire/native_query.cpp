#include "io/wire/native_query.h"

#include <algorithm>
#include <cmath>

#include "io/wire/byte_io.h"
#include "io/wire/crc32.h"

namespace ig::io::wire {

using bytes::Order;

namespace {

constexpr Order kLe = Order::Little;
constexpr std::size_t kCrcAt = kNativeQuerySize - 4;
constexpr std::uint8_t kFlagGeodetic = 1u << 0, kFlagValid = 1u << 1, kFlagHit = 1u << 2;

glm::dvec3 load3(const std::uint8_t* p) {
  return {bytes::load_f64(p, kLe), bytes::load_f64(p + 8, kLe), bytes::load_f64(p + 16, kLe)};
}
void store3(std::uint8_t* p, const glm::dvec3& v) {
  bytes::store_f64(p, v.x, kLe);
  bytes::store_f64(p + 8, v.y, kLe);
  bytes::store_f64(p + 16, v.z, kLe);
}
bool finite3(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool point_in_range(const glm::dvec3& p, bool geodetic) {
  if (geodetic) return p.x >= -90.0 && p.x <= 90.0 && p.y >= -180.0 && p.y < 360.0 && std::abs(p.z) < 1e6;
  return std::abs(p.x) < 1e8 && std::abs(p.y) < 1e8 && std::abs(p.z) < 1e6;
}

void seal(std::uint8_t* p) {
  bytes::store_u32(p + kCrcAt, crc32(std::span<const std::uint8_t>(p, kCrcAt)), kLe);
}
bool sealed(const std::uint8_t* p) {
  return bytes::load_u32(p + kCrcAt, kLe) == crc32(std::span<const std::uint8_t>(p, kCrcAt));
}

// A query and its answer open alike: [0] magic, [4] u16 version, [6] u8
// kind, [7] u8 flags, [8] u32 id.
std::array<std::uint8_t, kNativeQuerySize> open_packet(const std::array<std::uint8_t, 4>& magic, NativeQueryKind kind,
                                                       std::uint8_t flags, std::uint32_t id) {
  std::array<std::uint8_t, kNativeQuerySize> b{};
  std::copy(magic.begin(), magic.end(), b.begin());
  bytes::store_u16(b.data() + 4, kNativeQueryVersion, kLe);
  b[6] = std::uint8_t(kind);
  b[7] = flags;
  bytes::store_u32(b.data() + 8, id, kLe);
  return b;
}

}  // namespace

const char* native_query_reject_name(NativeQueryReject r) {
  switch (r) {
    case NativeQueryReject::WrongSize: return "wrong-size";
    case NativeQueryReject::BadMagic: return "bad-magic";
    case NativeQueryReject::BadVersion: return "bad-version";
    case NativeQueryReject::BadCrc: return "bad-crc";
    case NativeQueryReject::BadKind: return "bad-type";
    case NativeQueryReject::NonFinite: return "non-finite";
    case NativeQueryReject::OutOfRange: return "out-of-range";
  }
  return "unknown";
}

bool is_native_query(std::span<const std::uint8_t> d) {
  return d.size() >= 4 && std::equal(kNativeQueryMagic.begin(), kNativeQueryMagic.end(), d.begin());
}

// [0] "IGQR", [4] u16 version, [6] u8 kind, [7] u8 flags (bit 0 geodetic),
// [8] u32 id, [12] reserved, [16] a (3 x f64), [40] b (3 x f64),
// [64] f64 min range, [72] f64 max range, [80] reserved, [92] CRC-32 of [0, 92).
NativeQueryResult decode_native_query(std::span<const std::uint8_t> d) {
  NativeQueryResult r;
  if (d.size() != kNativeQuerySize) {
    r.reject = NativeQueryReject::WrongSize;
    return r;
  }
  const std::uint8_t* p = d.data();
  if (!is_native_query(d)) {
    r.reject = NativeQueryReject::BadMagic;
    return r;
  }
  if (bytes::load_u16(p + 4, kLe) != kNativeQueryVersion) {
    r.reject = NativeQueryReject::BadVersion;
    return r;
  }
  if (!sealed(p)) {
    r.reject = NativeQueryReject::BadCrc;
    return r;
  }
  NativeQuery q;
  if (p[6] < 1 || p[6] > 3) {
    r.reject = NativeQueryReject::BadKind;
    return r;
  }
  q.kind = NativeQueryKind(p[6]);
  q.geodetic = p[7] & kFlagGeodetic;
  q.id = bytes::load_u32(p + 8, kLe);
  q.a = load3(p + 16);
  q.b = load3(p + 40);
  q.min_range_m = bytes::load_f64(p + 64, kLe);
  q.max_range_m = bytes::load_f64(p + 72, kLe);
  const bool vector = q.kind == NativeQueryKind::LosVector;
  if (!finite3(q.a) || (q.kind != NativeQueryKind::Height && !finite3(q.b)) ||
      (vector && (!std::isfinite(q.min_range_m) || std::isnan(q.max_range_m)))) {
    r.reject = NativeQueryReject::NonFinite;
    return r;
  }
  if (!point_in_range(q.a, q.geodetic) || (q.kind == NativeQueryKind::LosSegment && !point_in_range(q.b, q.geodetic)) ||
      (vector && (q.min_range_m < 0.0 || q.max_range_m < q.min_range_m))) {
    r.reject = NativeQueryReject::OutOfRange;
    return r;
  }
  if (q.kind == NativeQueryKind::Height) q.b = glm::dvec3(0.0);
  if (!vector) q.min_range_m = q.max_range_m = 0.0;
  r.query = q;
  return r;
}

std::array<std::uint8_t, kNativeQuerySize> encode_native_query(const NativeQuery& q) {
  auto b = open_packet(kNativeQueryMagic, q.kind, q.geodetic ? kFlagGeodetic : 0, q.id);
  store3(b.data() + 16, q.a);
  store3(b.data() + 40, q.b);
  bytes::store_f64(b.data() + 64, q.min_range_m, kLe);
  bytes::store_f64(b.data() + 72, q.max_range_m, kLe);
  seal(b.data());
  return b;
}

// [0] "IGQA", [4] u16 version, [6] u8 kind, [7] u8 flags (bit 0 geodetic,
// 1 valid, 2 hit), [8] u32 id, [12] u32 IG frame, [16] f64 HOT / range,
// [24] f64 HAT, [32] point (3 x f64), [56] normal (3 x f64), [80] u32
// material code, [84] reserved, [92] CRC-32 of [0, 92).
std::array<std::uint8_t, kNativeQuerySize> encode_native_answer(const NativeAnswer& a) {
  const auto flags =
      std::uint8_t((a.geodetic ? kFlagGeodetic : 0) | (a.valid ? kFlagValid : 0) | (a.hit ? kFlagHit : 0));
  auto b = open_packet(kNativeAnswerMagic, a.kind, flags, a.id);
  bytes::store_u32(b.data() + 12, a.ig_frame, kLe);
  bytes::store_f64(b.data() + 16, a.hot_or_range_m, kLe);
  bytes::store_f64(b.data() + 24, a.hat_m, kLe);
  store3(b.data() + 32, a.point);
  store3(b.data() + 56, a.normal);
  bytes::store_u32(b.data() + 80, a.material, kLe);
  seal(b.data());
  return b;
}

std::optional<NativeAnswer> decode_native_answer(std::span<const std::uint8_t> d) {
  if (d.size() != kNativeQuerySize || !std::equal(kNativeAnswerMagic.begin(), kNativeAnswerMagic.end(), d.begin()))
    return std::nullopt;
  const std::uint8_t* p = d.data();
  if (bytes::load_u16(p + 4, kLe) != kNativeQueryVersion || !sealed(p)) return std::nullopt;
  NativeAnswer a;
  a.kind = NativeQueryKind(p[6]);
  a.geodetic = p[7] & kFlagGeodetic;
  a.valid = p[7] & kFlagValid;
  a.hit = p[7] & kFlagHit;
  a.id = bytes::load_u32(p + 8, kLe);
  a.ig_frame = bytes::load_u32(p + 12, kLe);
  a.hot_or_range_m = bytes::load_f64(p + 16, kLe);
  a.hat_m = bytes::load_f64(p + 24, kLe);
  a.point = load3(p + 32);
  a.normal = load3(p + 56);
  a.material = bytes::load_u32(p + 80, kLe);
  return a;
}

}  // namespace ig::io::wire
