// libFuzzer target: the CAN decoders as the pose source runs them. The input
// is a stream of frames (can_frame_stream.h), each handed to the CANaerospace
// decoder and pose assembler, or to the FD pose decoder on its id, with a
// receive time that advances 1 ms per frame (so staleness paths run too).
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "can_frame_stream.h"
#include "fuzz_check.h"
#include "io/wire/can_fd_pose.h"
#include "io/wire/canaerospace.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ig::io::wire;
  CanAerospaceStats stats;
  CanPoseAssembler assembler;
  double t = 0.0;
  for (const CanFrame& f : ig_fuzz::frames_from_bytes(data, size)) {
    t += 0.001;
    if (f.id == kCanFdPoseId) {
      ig_fuzz::check(decode_can_fd_pose(f));
      continue;
    }
    const auto v = decode_canaerospace(f, stats);
    if (v && v->data_type == kCanAsFloat && !std::isfinite(v->value)) __builtin_trap();
    if (v) assembler.feed(*v, t);
    StaleFields stale;
    const auto pose = assembler.pose(t, stale);
    if (pose && !is_valid_output(*pose)) __builtin_trap();
    if (pose && stale.reject) __builtin_trap();
  }
  if (stats.accepted + stats.rejected() != stats.frames) __builtin_trap();
  return 0;
}
