#pragma once
// Byte order of CIGI 3 traffic: the sender's from the IG Control / Start Of
// Frame magic (0x8000 read in its own order), ours for replies to a host
// whose order differs (CIGI lets the IG answer in either). Shared by the
// pose intake (cigi.cpp), host queries (cigi_queries.cpp) and views (cigi_views.cpp).

#include <cstdint>
#include <optional>

#include <span>

#include "io/wire/byte_io.h"
#include "io/wire/cigi.h"

namespace ig::io::wire {

// The sender's byte order from the two magic bytes, or nullopt.
inline std::optional<bytes::Order> cigi_order_from_magic(const std::uint8_t* m) {
  if (m[0] == 0x80 && m[1] == 0x00) return bytes::Order::Big;
  if (m[0] == 0x00 && m[1] == 0x80) return bytes::Order::Little;
  return std::nullopt;
}

// The order to write in: ours, or swapped to match the host's.
inline bytes::Order cigi_out_order(bool swap) { return swap ? bytes::swapped(bytes::kHostOrder) : bytes::kHostOrder; }

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

}  // namespace ig::io::wire
