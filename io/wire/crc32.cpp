#include "io/wire/crc32.h"

#include <zlib.h>

namespace ig::io::wire {

// zlib's crc32 is this CRC (and table-driven or vectorised on the machine).
std::uint32_t crc32_update(std::uint32_t crc, std::span<const std::uint8_t> data) {
  return std::uint32_t(::crc32(uLong(crc), data.data(), uInt(data.size())));
}

std::uint32_t crc32(std::span<const std::uint8_t> data) { return crc32_update(0u, data); }

}  // namespace ig::io::wire
