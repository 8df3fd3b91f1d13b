#pragma once
// A hash of three integers to 32 well-mixed bits (lowbias32's finaliser):
// lattice values for procedural terrain and ground detail, the same on every
// machine, without a table.
#include <cstdint>

namespace ig::terrain {

inline std::uint32_t hash3(std::uint32_t x, std::uint32_t y, std::uint32_t s) {
  std::uint32_t h = x * 0x8DA6B343u + y * 0xD8163841u + s * 0xCB1AB31Fu + 0x165667B1u;
  h ^= h >> 16;
  h *= 0x7FEB352Du;
  h ^= h >> 15;
  h *= 0x846CA68Bu;
  h ^= h >> 16;
  return h;
}

}  // namespace ig::terrain
