#pragma once
// Shared invariant for the wire fuzz targets: a decoder returns exactly one
// of pose / reject, and an accepted pose is finite and in range.

#include "io/wire/pose_message.h"

namespace ig_fuzz {

inline void check(const ig::io::wire::DecodeResult& r) {
  if (r.pose.has_value() == r.reject.has_value()) __builtin_trap();
  if (r.pose && !ig::io::wire::is_valid_output(*r.pose)) __builtin_trap();
  if (r.ig_mode && *r.ig_mode > 3u) __builtin_trap();
}

}  // namespace ig_fuzz
