#include "io/wire/cigi.h"

#include <cmath>

#include "io/wire/byte_io.h"
#include "io/wire/cigi_byte_order.h"
#include "io/wire/cigi_host_datagram.h"

namespace ig::io::wire {

using bytes::Order;

namespace {

std::uint32_t timestamp_10us(double seconds) {
  if (!std::isfinite(seconds)) return 0;
  const double ticks = std::round(seconds * 1e5);
  const double wrapped = ticks - 4294967296.0 * std::floor(ticks / 4294967296.0);
  if (!(wrapped >= 0.0 && wrapped < 4294967296.0)) return 0;
  return static_cast<std::uint32_t>(wrapped);
}

// IG Control bit 2 / Start Of Frame bit 2.
constexpr std::uint8_t kTimestampValid = 1u << 2;

}  // namespace

std::vector<std::uint8_t> encode_cigi_host_datagram(std::uint32_t host_frame, std::uint32_t ig_mode,
                                                    const PoseMessage& pose, bool swap) {
  const Order o = cigi_out_order(swap);
  std::vector<std::uint8_t> b(kCigiIgControlSize + kCigiEntityControlSize, 0);
  std::uint8_t* ig = b.data();
  ig[0] = kCigiOpIgControl;
  ig[1] = static_cast<std::uint8_t>(kCigiIgControlSize);
  ig[2] = kCigiMajorVersion;
  ig[3] = 0;  // database number: no change
  ig[4] = static_cast<std::uint8_t>((ig_mode & 0x3u) | (pose.has_sender_time ? kTimestampValid : 0u) |
                                    (kCigiMinorVersion << 4));
  bytes::store_u16(ig + 6, kCigiByteSwapMagic, o);
  bytes::store_u32(ig + 8, host_frame, o);
  bytes::store_u32(ig + 12, pose.has_sender_time ? timestamp_10us(pose.sender_time_s) : 0u, o);
  bytes::store_u32(ig + 16, 0u, o);  // last IG frame number: unknown to the encoder

  std::uint8_t* ec = b.data() + kCigiIgControlSize;
  ec[0] = kCigiOpEntityControl;
  ec[1] = static_cast<std::uint8_t>(kCigiEntityControlSize);
  bytes::store_u16(ec + 2, kCigiOwnshipEntity, o);
  ec[4] = 1;    // entity state active, detached, no clamping
  ec[6] = 255;  // alpha
  bytes::store_u16(ec + 8, 0, o);   // entity type
  bytes::store_u16(ec + 10, 0, o);  // parent id
  bytes::store_f32(ec + 12, bytes::narrow_f32(pose.roll_deg), o);
  bytes::store_f32(ec + 16, bytes::narrow_f32(pose.pitch_deg), o);
  bytes::store_f32(ec + 20, bytes::narrow_f32(pose.heading_deg), o);
  bytes::store_f64(ec + 24, pose.position.x, o);
  bytes::store_f64(ec + 32, pose.position.y, o);
  bytes::store_f64(ec + 40, pose.position.z, o);
  return b;
}

DecodeResult decode_cigi_host_datagram(std::span<const std::uint8_t> data) { return decode_cigi(data).ownship; }

std::array<std::uint8_t, kCigiStartOfFrameSize> encode_cigi_start_of_frame(
    std::uint32_t ig_frame, std::uint32_t last_host_frame, std::uint32_t timestamp_10us_value,
    std::uint32_t ig_mode, bool swap, std::uint8_t ig_status) {
  const Order o = cigi_out_order(swap);
  std::array<std::uint8_t, kCigiStartOfFrameSize> b{};
  std::uint8_t* p = b.data();
  p[0] = kCigiOpStartOfFrame;
  p[1] = static_cast<std::uint8_t>(kCigiStartOfFrameSize);
  p[2] = kCigiMajorVersion;
  p[3] = 0;  // database number
  p[4] = ig_status;
  p[5] = static_cast<std::uint8_t>((ig_mode & 0x3u) | kTimestampValid | (kCigiMinorVersion << 4));
  bytes::store_u16(p + 6, kCigiByteSwapMagic, o);
  bytes::store_u32(p + 8, ig_frame, o);
  bytes::store_u32(p + 12, timestamp_10us_value, o);
  bytes::store_u32(p + 16, last_host_frame, o);
  return b;
}

StartOfFrameResult decode_cigi_start_of_frame(std::span<const std::uint8_t> data) {
  StartOfFrameResult r;
  const auto order = cigi_check_first_packet(data, kCigiOpStartOfFrame, kCigiStartOfFrameSize, Reject::Truncated, r.reject);
  if (!order) return r;
  const std::uint8_t* p = data.data();
  const Order o = *order;
  CigiStartOfFrame s;
  s.ig_status = p[4];
  s.ig_mode = p[5] & 0x3u;
  s.timestamp_valid = (p[5] & kTimestampValid) != 0;
  s.minor_version = static_cast<std::uint8_t>(p[5] >> 4);
  s.ig_frame = bytes::load_u32(p + 8, o);
  s.timestamp_10us = bytes::load_u32(p + 12, o);
  s.last_host_frame = bytes::load_u32(p + 16, o);
  s.byte_swapped = (o != bytes::kHostOrder);
  r.sof = s;
  return r;
}

}  // namespace ig::io::wire
