#pragma once
// Fuzz input <-> a stream of CAN frames: each frame is 4 header bytes (id low,
// id high, flags, length) then `length` data bytes (clamped to the input).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "io/wire/can_frame.h"

namespace ig_fuzz {

inline std::vector<ig::io::wire::CanFrame> frames_from_bytes(const std::uint8_t* data, std::size_t size) {
  std::vector<ig::io::wire::CanFrame> out;
  std::size_t i = 0;
  while (i + 4 <= size) {
    ig::io::wire::CanFrame f;
    f.id = std::uint32_t(data[i]) | (std::uint32_t(data[i + 1]) << 8);
    f.flags = data[i + 2];
    const std::size_t len = std::min<std::size_t>({data[i + 3], ig::io::wire::kCanFdMaxLen, size - i - 4});
    f.len = std::uint8_t(len);
    std::copy(data + i + 4, data + i + 4 + len, f.data.begin());
    out.push_back(f);
    i += 4 + len;
  }
  return out;
}

inline void append_frame_bytes(std::vector<std::uint8_t>& out, const ig::io::wire::CanFrame& f) {
  out.push_back(std::uint8_t(f.id));
  out.push_back(std::uint8_t(f.id >> 8));
  out.push_back(f.flags);
  out.push_back(f.len);
  out.insert(out.end(), f.data.begin(), f.data.begin() + f.len);
}

}  // namespace ig_fuzz
