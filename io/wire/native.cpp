#include "io/wire/native.h"

#include <algorithm>

#include "io/wire/byte_io.h"
#include "io/wire/crc32.h"

namespace ig::io::wire {

namespace off = native_offset;
using bytes::Order;

std::array<std::uint8_t, kNativeSize> encode_native(const PoseMessage& pose) {
  std::array<std::uint8_t, kNativeSize> b{};
  std::uint8_t* p = b.data();
  const Order le = Order::Little;
  std::copy(kNativeMagic.begin(), kNativeMagic.end(), p + off::kMagic);
  bytes::store_u16(p + off::kVersion, kNativeVersion, le);
  bytes::store_u16(p + off::kFlags, pose_content_flags(pose), le);
  bytes::store_u32(p + off::kSequence, pose.has_sequence ? pose.sequence : 0u, le);
  bytes::store_f64(p + off::kSenderTime, pose.has_sender_time ? pose.sender_time_s : 0.0, le);
  for (int i = 0; i < 3; ++i) bytes::store_f64(p + off::kPosition + 8 * i, pose.position[i], le);
  bytes::store_f64(p + off::kAttitude + 0, pose.heading_deg, le);
  bytes::store_f64(p + off::kAttitude + 8, pose.pitch_deg, le);
  bytes::store_f64(p + off::kAttitude + 16, pose.roll_deg, le);
  for (int i = 0; i < 3; ++i) {
    const float rate = pose.has_rates ? bytes::narrow_f32(pose.body_rates_dps[i]) : 0.0f;
    const float vel = pose.has_velocity ? bytes::narrow_f32(pose.velocity_mps[i]) : 0.0f;
    bytes::store_f32(p + off::kBodyRates + 4 * i, rate, le);
    bytes::store_f32(p + off::kVelocity + 4 * i, vel, le);
  }
  const std::uint32_t crc = crc32(std::span<const std::uint8_t>(p, off::kCrc));
  bytes::store_u32(p + off::kCrc, crc, le);
  return b;
}

DecodeResult decode_native(std::span<const std::uint8_t> data) {
  if (auto why = fixed_size_reject(data.size(), kNativeSize)) return rejected(*why);
  const std::uint8_t* p = data.data();
  const Order le = Order::Little;
  if (!std::equal(kNativeMagic.begin(), kNativeMagic.end(), p + off::kMagic)) return rejected(Reject::BadMagic);
  if (bytes::load_u16(p + off::kVersion, le) != kNativeVersion) return rejected(Reject::BadVersion);
  if (crc32(std::span<const std::uint8_t>(p, off::kCrc)) != bytes::load_u32(p + off::kCrc, le)) return rejected(Reject::BadCrc);

  PoseMessage m;
  apply_pose_content_flags(bytes::load_u16(p + off::kFlags, le), m);
  if (m.has_sequence) m.sequence = bytes::load_u32(p + off::kSequence, le);
  if (m.has_sender_time) m.sender_time_s = bytes::load_f64(p + off::kSenderTime, le);
  for (int i = 0; i < 3; ++i) m.position[i] = bytes::load_f64(p + off::kPosition + 8 * i, le);
  m.heading_deg = bytes::load_f64(p + off::kAttitude + 0, le);
  m.pitch_deg = bytes::load_f64(p + off::kAttitude + 8, le);
  m.roll_deg = bytes::load_f64(p + off::kAttitude + 16, le);
  for (int i = 0; i < 3; ++i) {
    if (m.has_rates) m.body_rates_dps[i] = bytes::load_f32(p + off::kBodyRates + 4 * i, le);
    if (m.has_velocity) m.velocity_mps[i] = bytes::load_f32(p + off::kVelocity + 4 * i, le);
  }
  return finish_decode(m);
}

}  // namespace ig::io::wire
