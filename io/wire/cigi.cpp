#include "io/wire/cigi.h"

#include <cmath>

#include "io/wire/byte_io.h"
#include "io/wire/cigi_byte_order.h"

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
// Entity Control byte 4, bit 2: attached to a parent (position is relative).
constexpr std::uint8_t kEntityAttached = 1u << 2;

// The checks every datagram's first packet passes, in this order: datagram
// size, opcode, packet size (0 is Truncated, any other wrong size
// `wrong_size`), major version, byte-swap magic. The byte order, or nullopt
// with `reject` set.
std::optional<Order> check_first_packet(std::span<const std::uint8_t> data, std::uint8_t opcode,
                                        std::size_t packet_size, Reject wrong_size, std::optional<Reject>& reject) {
  const std::size_t n = data.size();
  const std::uint8_t* p = data.data();
  if (n < packet_size) reject = Reject::TooShort;
  else if (n > kCigiMaxDatagram) reject = Reject::TooLong;
  else if (p[0] != opcode) reject = Reject::UnknownPacket;
  else if (p[1] == 0) reject = Reject::Truncated;
  else if (p[1] != packet_size) reject = wrong_size;
  else if (p[2] != kCigiMajorVersion) reject = Reject::BadVersion;
  if (reject) return std::nullopt;
  const std::optional<Order> order = cigi_order_from_magic(p + 6);
  if (!order) reject = Reject::BadMagic;
  return order;
}

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

DecodeResult decode_cigi_host_datagram(std::span<const std::uint8_t> data) {
  DecodeResult r;
  // A wrong IG Control size reads as another CIGI version's packet.
  const auto order = check_first_packet(data, kCigiOpIgControl, kCigiIgControlSize, Reject::BadVersion, r.reject);
  if (!order) return r;
  const std::size_t n = data.size();
  const std::uint8_t* p = data.data();
  const Order o = *order;
  r.byte_swapped = (o != bytes::kHostOrder);
  const std::uint32_t host_frame = bytes::load_u32(p + 8, o);
  const bool ts_valid = (p[4] & kTimestampValid) != 0;
  const std::uint32_t ts = bytes::load_u32(p + 12, o);
  r.host_frame = host_frame;
  r.ig_mode = p[4] & 0x3u;

  const std::uint8_t* ownship = nullptr;
  std::size_t off = kCigiIgControlSize;
  while (off < n) {
    if (n - off < 2) {
      r.reject = Reject::Truncated;
      return r;
    }
    const std::uint8_t op = p[off];
    const std::size_t size = p[off + 1];
    if (size == 0 || size > n - off) {
      r.reject = Reject::Truncated;
      return r;
    }
    if (op == kCigiOpEntityControl) {
      if (size != kCigiEntityControlSize) {
        r.reject = Reject::Truncated;
        return r;
      }
      const std::uint8_t* ec = p + off;
      if (bytes::load_u16(ec + 2, o) == kCigiOwnshipEntity && (ec[4] & kEntityAttached) == 0) {
        ownship = ec;
      }
    }
    // Every other opcode (IG Control repeats included) is skipped by its size.
    off += size;
  }
  if (!ownship) {
    r.reject = Reject::NoPose;
    return r;
  }

  PoseMessage m;
  m.frame = PoseMessage::Frame::Geodetic;
  m.roll_deg = bytes::load_f32(ownship + 12, o);
  m.pitch_deg = bytes::load_f32(ownship + 16, o);
  m.heading_deg = bytes::load_f32(ownship + 20, o);
  m.position.x = bytes::load_f64(ownship + 24, o);
  m.position.y = bytes::load_f64(ownship + 32, o);
  m.position.z = bytes::load_f64(ownship + 40, o);
  m.host_frame = host_frame;
  m.sequence = host_frame;
  m.has_sequence = true;
  if (ts_valid) {
    m.sender_time_s = static_cast<double>(ts) * 1e-5;
    m.has_sender_time = true;
  }
  return finish_decode(m, r);
}

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
  const auto order = check_first_packet(data, kCigiOpStartOfFrame, kCigiStartOfFrameSize, Reject::Truncated, r.reject);
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
