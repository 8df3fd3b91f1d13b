#pragma once
// Bounds-free little helpers to read and write fixed-width fields at a byte
// offset in a chosen byte order. Callers check sizes first; these never
// allocate and never assume the host byte order (memcpy-free shifts).

#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace ig::io::wire::bytes {

enum class Order { Little, Big };

inline constexpr Order kHostOrder =
    std::endian::native == std::endian::big ? Order::Big : Order::Little;

inline Order swapped(Order o) { return o == Order::Little ? Order::Big : Order::Little; }

inline std::uint64_t load_uint(const std::uint8_t* p, int n, Order o) {
  std::uint64_t v = 0;
  for (int i = 0; i < n; ++i) {
    const int idx = (o == Order::Big) ? i : (n - 1 - i);
    v = (v << 8) | p[idx];
  }
  return v;
}

inline void store_uint(std::uint8_t* p, std::uint64_t v, int n, Order o) {
  for (int i = 0; i < n; ++i) {
    const int idx = (o == Order::Little) ? i : (n - 1 - i);
    p[idx] = static_cast<std::uint8_t>(v & 0xFFu);
    v >>= 8;
  }
}

inline std::uint16_t load_u16(const std::uint8_t* p, Order o) {
  return static_cast<std::uint16_t>(load_uint(p, 2, o));
}
inline std::uint32_t load_u32(const std::uint8_t* p, Order o) {
  return static_cast<std::uint32_t>(load_uint(p, 4, o));
}
inline std::uint64_t load_u64(const std::uint8_t* p, Order o) { return load_uint(p, 8, o); }
inline float load_f32(const std::uint8_t* p, Order o) { return std::bit_cast<float>(load_u32(p, o)); }
inline double load_f64(const std::uint8_t* p, Order o) { return std::bit_cast<double>(load_u64(p, o)); }

inline void store_u16(std::uint8_t* p, std::uint16_t v, Order o) { store_uint(p, v, 2, o); }
inline void store_u32(std::uint8_t* p, std::uint32_t v, Order o) { store_uint(p, v, 4, o); }
inline void store_u64(std::uint8_t* p, std::uint64_t v, Order o) { store_uint(p, v, 8, o); }
inline void store_f32(std::uint8_t* p, float v, Order o) { store_u32(p, std::bit_cast<std::uint32_t>(v), o); }
inline void store_f64(std::uint8_t* p, double v, Order o) { store_u64(p, std::bit_cast<std::uint64_t>(v), o); }

// double -> float without the undefined behaviour of an out-of-range cast:
// too-large magnitudes become +-Inf (the receiver rejects them), NaN stays NaN.
inline float narrow_f32(double v) {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (v > kMax) return std::numeric_limits<float>::infinity();
  if (v < -kMax) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(v);
}

}  // namespace ig::io::wire::bytes
