#pragma once
// Shared helpers for the CAN codec tests (wire_canaerospace_test.cpp,
// wire_can_fd_test.cpp; header only).

#include <vector>

#include "io/test/wire_test_support.h"
#include "io/wire/can_frame.h"
#include "io/wire/can_fd_pose.h"
#include "io/wire/canaerospace.h"

namespace can_test {

using namespace ig::io::wire;
using wire_test::angle_diff;
using wire_test::random_pose;

inline PoseMessage sample_pose() {
  return wire_test::sample_geodetic_pose({37.6189123456789, -122.375987654321, 120.5});
}

// Decodes `frames` and feeds every accepted value at time t.
inline void feed_all(const std::vector<CanFrame>& frames, CanAerospaceStats& st, CanPoseAssembler& as, double t,
                     const CanAerospaceOptions& opt = {}) {
  for (const auto& f : frames) {
    if (auto v = decode_canaerospace(f, st, opt)) as.feed(*v, t);
  }
}

}  // namespace can_test
