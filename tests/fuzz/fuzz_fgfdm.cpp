// libFuzzer target: FlightGear FGNetFDM v24 decoder.
#include <cstddef>
#include <cstdint>
#include <span>

#include "fuzz_check.h"
#include "io/wire/fgnetfdm.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ig::io::wire;
  const DecodeResult r = decode_fgnetfdm(std::span<const std::uint8_t>(data, size));
  ig_fuzz::check(r);
  if (r.pose && !(r.pose->has_rates && r.pose->has_velocity)) __builtin_trap();
  return 0;
}
