#pragma once
// CRC-32 as in IEEE 802.3 / zlib / PNG: reflected, polynomial 0xEDB88320,
// initial value 0xFFFFFFFF, final XOR 0xFFFFFFFF. crc32("123456789") ==
// 0xCBF43926.

#include <cstdint>
#include <span>

namespace ig::io::wire {

std::uint32_t crc32(std::span<const std::uint8_t> data);

// Incremental form: start with crc = 0, feed chunks, the result is final.
std::uint32_t crc32_update(std::uint32_t crc, std::span<const std::uint8_t> data);

}  // namespace ig::io::wire
