#pragma once
// Byte order of CIGI 3 traffic: the sender's from the IG Control / Start Of
// Frame magic (0x8000 read in its own order), ours for replies to a host
// whose order differs (CIGI lets the IG answer in either). Shared by the
// pose intake (cigi.cpp), host queries (cigi_queries.cpp) and views (cigi_views.cpp).
// Also the packet walk of a host datagram the query and view decoders share.

#include <cstddef>
#include <cstdint>
#include <optional>

#include <span>

#include "io/wire/byte_io.h"
#include "io/wire/cigi.h"
#include "io/wire/pose_message.h"

namespace ig::io::wire {

// The sender's byte order from the two magic bytes, or nullopt.
inline std::optional<bytes::Order> cigi_order_from_magic(const std::uint8_t* m) {
  if (m[0] == 0x80 && m[1] == 0x00) return bytes::Order::Big;
  if (m[0] == 0x00 && m[1] == 0x80) return bytes::Order::Little;
  return std::nullopt;
}

// The order to write in: ours, or swapped to match the host's.
inline bytes::Order cigi_out_order(bool swap) { return swap ? bytes::swapped(bytes::kHostOrder) : bytes::kHostOrder; }

// The checks every datagram's first packet passes, in this order: datagram
// size, opcode, packet size (0 is Truncated, any other wrong size
// `wrong_size`), major version, byte-swap magic. The byte order, or nullopt
// with `reject` set.
inline std::optional<bytes::Order> cigi_check_first_packet(std::span<const std::uint8_t> data, std::uint8_t opcode,
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
  const std::optional<bytes::Order> order = cigi_order_from_magic(p + 6);
  if (!order) reject = Reject::BadMagic;
  return order;
}


// The sender's order of a host datagram that starts with a well-formed IG
// Control of our major version and fits the size limit; nullopt otherwise
// (the pose intake reports the reason; the query and view decoders skip).
inline std::optional<bytes::Order> cigi_host_datagram_order(std::span<const std::uint8_t> data) {
  const std::uint8_t* p = data.data();
  if (data.size() < kCigiIgControlSize || data.size() > kCigiMaxDatagram || p[0] != kCigiOpIgControl ||
      p[1] != kCigiIgControlSize || p[2] != kCigiMajorVersion)
    return std::nullopt;
  return cigi_order_from_magic(p + 6);
}

// Walks the packets after a host datagram's IG Control: on_packet(op, packet,
// size) for each one its size byte frames; where the rest cannot be framed
// (size 0 or past the end), on_truncated(op) and the walk ends.
template <class OnPacket, class OnTruncated>
void for_each_cigi_host_packet(std::span<const std::uint8_t> data, OnPacket&& on_packet, OnTruncated&& on_truncated) {
  const std::size_t n = data.size();
  const std::uint8_t* p = data.data();
  for (std::size_t off = kCigiIgControlSize; off < n;) {
    const std::size_t left = n - off;
    const std::size_t size = left >= 2 ? p[off + 1] : 0;
    if (size == 0 || size > left) {
      on_truncated(p[off]);
      return;
    }
    on_packet(p[off], p + off, size);
    off += size;
  }
}

// Walks the packets after an IG datagram's Start Of Frame (`sof_size`
// bytes): on_packet(op, packet, size) for each; false where a packet cannot
// be framed (size 0 or past the end).
template <class OnPacket>
bool for_each_cigi_ig_packet(std::span<const std::uint8_t> data, std::size_t sof_size, OnPacket&& on_packet) {
  const std::uint8_t* p = data.data();
  for (std::size_t off = sof_size; off < data.size();) {
    const std::size_t left = data.size() - off;
    if (left < 2 || p[off + 1] == 0 || p[off + 1] > left) return false;
    on_packet(p[off], p + off, std::size_t(p[off + 1]));
    off += p[off + 1];
  }
  return true;
}

}  // namespace ig::io::wire
