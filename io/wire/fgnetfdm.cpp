#include "io/wire/fgnetfdm.h"

#include <cmath>

#include "io/wire/byte_io.h"

namespace ig::io::wire {

namespace off = fgfdm_offset;
using bytes::Order;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegToRad = kPi / 180.0;
constexpr double kRadToDeg = 180.0 / kPi;
constexpr double kFtToM = 0.3048;
constexpr double kKtToMps = 1852.0 / 3600.0;
constexpr Order kBe = Order::Big;

void put_f32(std::uint8_t* p, std::size_t at, double v) { bytes::store_f32(p + at, bytes::narrow_f32(v), kBe); }
double get_f32(const std::uint8_t* p, std::size_t at) { return bytes::load_f32(p + at, kBe); }

}  // namespace

std::array<std::uint8_t, kFgNetFdmSize> encode_fgnetfdm(const PoseMessage& pose) {
  std::array<std::uint8_t, kFgNetFdmSize> b{};
  std::uint8_t* p = b.data();
  bytes::store_u32(p + off::kVersion, kFgNetFdmVersion, kBe);
  bytes::store_f64(p + off::kLongitude, pose.position.y * kDegToRad, kBe);
  bytes::store_f64(p + off::kLatitude, pose.position.x * kDegToRad, kBe);
  bytes::store_f64(p + off::kAltitude, pose.position.z, kBe);
  put_f32(p, off::kPhi, pose.roll_deg * kDegToRad);
  put_f32(p, off::kTheta, pose.pitch_deg * kDegToRad);
  put_f32(p, off::kPsi, pose.heading_deg * kDegToRad);
  if (pose.has_rates) {
    put_f32(p, off::kPhiDot, pose.body_rates_dps.x * kDegToRad);
    put_f32(p, off::kThetaDot, pose.body_rates_dps.y * kDegToRad);
    put_f32(p, off::kPsiDot, pose.body_rates_dps.z * kDegToRad);
  }
  if (pose.has_velocity) {
    const glm::dvec3& v = pose.velocity_mps;  // ENU
    put_f32(p, off::kVNorth, v.y / kFtToM);
    put_f32(p, off::kVEast, v.x / kFtToM);
    put_f32(p, off::kVDown, -v.z / kFtToM);
    put_f32(p, off::kClimbRate, v.z / kFtToM);
    put_f32(p, off::kVcas, std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z) / kKtToMps);
  }
  std::uint32_t cur_time = 0;
  if (pose.has_sender_time && pose.sender_time_s >= 0.0 && pose.sender_time_s < 4294967296.0) {
    cur_time = static_cast<std::uint32_t>(pose.sender_time_s);
  }
  bytes::store_u32(p + off::kCurTime, cur_time, kBe);
  put_f32(p, off::kVisibility, 10000.0);
  return b;
}

DecodeResult decode_fgnetfdm(std::span<const std::uint8_t> data) {
  if (auto why = fixed_size_reject(data.size(), kFgNetFdmSize)) return rejected(*why);
  const std::uint8_t* p = data.data();
  if (bytes::load_u32(p + off::kVersion, kBe) != kFgNetFdmVersion) return rejected(Reject::BadVersion);
  PoseMessage m;
  m.frame = PoseMessage::Frame::Geodetic;
  // Check the raw values first: a huge finite radian value times 180/pi
  // could overflow to Inf and be mis-reported as NonFinite.
  const double lon_rad = bytes::load_f64(p + off::kLongitude, kBe);
  const double lat_rad = bytes::load_f64(p + off::kLatitude, kBe);
  const double alt_m = bytes::load_f64(p + off::kAltitude, kBe);
  if (!std::isfinite(lon_rad) || !std::isfinite(lat_rad) || !std::isfinite(alt_m)) return rejected(Reject::NonFinite);
  if (std::fabs(lon_rad) > 10.0 || std::fabs(lat_rad) > 10.0) return rejected(Reject::OutOfRange);
  double lat = lat_rad * kRadToDeg, lon = lon_rad * kRadToDeg;
  // A pole or the antimeridian converted by the sender with another pi may
  // land a rounding step outside the range: clamp those, reject the rest.
  constexpr double kSlack = 1e-9;
  if (lat > 90.0 && lat <= 90.0 + kSlack) lat = 90.0;
  if (lat < -90.0 && lat >= -90.0 - kSlack) lat = -90.0;
  if (lon < -180.0 && lon >= -180.0 - kSlack) lon = -180.0;
  m.position = glm::dvec3(lat, lon, alt_m);
  // f32 angles / rates / speeds cannot overflow a double when scaled.
  m.roll_deg = get_f32(p, off::kPhi) * kRadToDeg;
  m.pitch_deg = get_f32(p, off::kTheta) * kRadToDeg;
  m.heading_deg = get_f32(p, off::kPsi) * kRadToDeg;
  m.body_rates_dps = glm::dvec3(get_f32(p, off::kPhiDot), get_f32(p, off::kThetaDot), get_f32(p, off::kPsiDot)) *
                     kRadToDeg;
  m.has_rates = true;
  const double vn = get_f32(p, off::kVNorth), ve = get_f32(p, off::kVEast), vd = get_f32(p, off::kVDown);
  m.velocity_mps = glm::dvec3(ve, vn, -vd) * kFtToM;
  m.has_velocity = true;
  return finish_decode(m);
}

}  // namespace ig::io::wire
