#include "io/wire/can_fd_pose.h"

#include <cmath>
#include <span>

#include "io/wire/byte_io.h"
#include "io/wire/crc32.h"

namespace ig::io::wire {

namespace off = can_fd_offset;
using bytes::Order;

namespace {

std::int16_t to_i16(double v, double scale) {
  if (!std::isfinite(v)) return kCanFdI16NonFinite;
  const double c = std::round(v / scale);
  if (c >= 32767.0) return 32767;
  if (c <= -32767.0) return -32767;
  return static_cast<std::int16_t>(c);
}

double from_i16(std::int16_t raw, double scale) {
  if (raw == kCanFdI16NonFinite) return std::nan("");
  return static_cast<double>(raw) * scale;
}

}  // namespace

CanFrame encode_can_fd_pose(const PoseMessage& pose) {
  CanFrame f;
  f.id = kCanFdPoseId;
  f.flags = kCanFlagFd | kCanFlagBrs;
  f.len = static_cast<std::uint8_t>(kCanFdPoseSize);
  std::uint8_t* p = f.data.data();
  const Order le = Order::Little;
  p[off::kMagic] = kCanFdPoseMagic0;
  p[off::kMagic + 1] = kCanFdPoseMagic1;
  p[off::kVersion] = kCanFdPoseVersion;
  p[off::kFlags] = static_cast<std::uint8_t>(pose_content_flags(pose));
  bytes::store_u32(p + off::kSequence, pose.has_sequence ? pose.sequence : 0u, le);
  bytes::store_f64(p + off::kSenderTime, pose.has_sender_time ? pose.sender_time_s : 0.0, le);
  bytes::store_f64(p + off::kPositionXY, pose.position.x, le);
  bytes::store_f64(p + off::kPositionXY + 8, pose.position.y, le);
  bytes::store_f32(p + off::kPositionZ, bytes::narrow_f32(pose.position.z), le);
  bytes::store_f32(p + off::kAttitude + 0, bytes::narrow_f32(pose.heading_deg), le);
  bytes::store_f32(p + off::kAttitude + 4, bytes::narrow_f32(pose.pitch_deg), le);
  bytes::store_f32(p + off::kAttitude + 8, bytes::narrow_f32(pose.roll_deg), le);
  for (int i = 0; i < 3; ++i) {
    const std::int16_t rate = pose.has_rates ? to_i16(pose.body_rates_dps[i], kCanFdRateScale) : 0;
    const std::int16_t vel = pose.has_velocity ? to_i16(pose.velocity_mps[i], kCanFdVelocityScale) : 0;
    bytes::store_u16(p + off::kBodyRates + 2 * i, static_cast<std::uint16_t>(rate), le);
    bytes::store_u16(p + off::kVelocity + 2 * i, static_cast<std::uint16_t>(vel), le);
  }
  const std::uint32_t crc = crc32(std::span<const std::uint8_t>(p, off::kCrc));
  bytes::store_u32(p + off::kCrc, crc, le);
  return f;
}

DecodeResult decode_can_fd_pose(const CanFrame& frame) {
  if (frame.id != kCanFdPoseId || (frame.flags & (kCanFlagExtended | kCanFlagRtr | kCanFlagError)) != 0) return rejected(Reject::UnknownPacket);
  if (!frame.is_fd() || frame.len < kCanFdPoseSize) return rejected(Reject::TooShort);
  if (frame.len > kCanFdPoseSize) return rejected(Reject::TooLong);
  const std::uint8_t* p = frame.data.data();
  const Order le = Order::Little;
  if (p[off::kMagic] != kCanFdPoseMagic0 || p[off::kMagic + 1] != kCanFdPoseMagic1) return rejected(Reject::BadMagic);
  if (p[off::kVersion] != kCanFdPoseVersion) return rejected(Reject::BadVersion);
  if (crc32(std::span<const std::uint8_t>(p, off::kCrc)) != bytes::load_u32(p + off::kCrc, le)) return rejected(Reject::BadCrc);
  PoseMessage m;
  apply_pose_content_flags(p[off::kFlags], m);
  if (m.has_sequence) m.sequence = bytes::load_u32(p + off::kSequence, le);
  if (m.has_sender_time) m.sender_time_s = bytes::load_f64(p + off::kSenderTime, le);
  m.position.x = bytes::load_f64(p + off::kPositionXY, le);
  m.position.y = bytes::load_f64(p + off::kPositionXY + 8, le);
  m.position.z = bytes::load_f32(p + off::kPositionZ, le);
  m.heading_deg = bytes::load_f32(p + off::kAttitude + 0, le);
  m.pitch_deg = bytes::load_f32(p + off::kAttitude + 4, le);
  m.roll_deg = bytes::load_f32(p + off::kAttitude + 8, le);
  for (int i = 0; i < 3; ++i) {
    if (m.has_rates) {
      const auto raw = static_cast<std::int16_t>(bytes::load_u16(p + off::kBodyRates + 2 * i, le));
      m.body_rates_dps[i] = from_i16(raw, kCanFdRateScale);
    }
    if (m.has_velocity) {
      const auto raw = static_cast<std::int16_t>(bytes::load_u16(p + off::kVelocity + 2 * i, le));
      m.velocity_mps[i] = from_i16(raw, kCanFdVelocityScale);
    }
  }
  return finish_decode(m);
}

}  // namespace ig::io::wire
