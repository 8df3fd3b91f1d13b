// libFuzzer target: native IGPS decoder. Besides the raw input, a 128-byte
// input is also decoded with its CRC fixed, so the value checks behind the
// CRC get fuzzed too.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

#include "fuzz_check.h"
#include "io/wire/crc32.h"
#include "io/wire/native.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ig::io::wire;
  ig_fuzz::check(decode_native(std::span<const std::uint8_t>(data, size)));
  if (size == kNativeSize) {
    std::array<std::uint8_t, kNativeSize> b;
    std::memcpy(b.data(), data, size);
    const std::uint32_t c = crc32(std::span<const std::uint8_t>(b.data(), native_offset::kCrc));
    for (int i = 0; i < 4; ++i) b[native_offset::kCrc + i] = static_cast<std::uint8_t>(c >> (8 * i));
    const DecodeResult r = decode_native(b);
    ig_fuzz::check(r);
    if (r.reject == Reject::BadCrc) __builtin_trap();
    // Accepted poses re-encode and decode to the same pose.
    if (r.pose) {
      const DecodeResult again = decode_native(encode_native(*r.pose));
      if (!again.pose) __builtin_trap();
    }
  }
  return 0;
}
