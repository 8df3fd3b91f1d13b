// libFuzzer target: CIGI 3.3 host datagram and Start Of Frame decoders.
#include <cstddef>
#include <cstdint>
#include <span>

#include "fuzz_check.h"
#include "io/wire/cigi.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ig::io::wire;
  const std::span<const std::uint8_t> in(data, size);
  const DecodeResult r = decode_cigi_host_datagram(in);
  ig_fuzz::check(r);
  if (r.reject == Reject::NoPose && (!r.host_frame || !r.ig_mode)) __builtin_trap();
  if (r.pose) {
    // An accepted ownship re-encodes (both byte orders) to an accepted datagram.
    for (bool swap : {false, true}) {
      const DecodeResult again =
          decode_cigi_host_datagram(encode_cigi_host_datagram(*r.host_frame, *r.ig_mode, *r.pose, swap));
      if (!again.pose) __builtin_trap();
    }
  }
  const StartOfFrameResult s = decode_cigi_start_of_frame(in);
  if (s.sof.has_value() == s.reject.has_value()) __builtin_trap();
  if (s.sof && s.sof->ig_mode > 3u) __builtin_trap();
  return 0;
}
