#pragma once
// A host's pose stream, the part a sender (ig send) and a test host share:
// the pose message for a moment of a path, and its encoding as one datagram
// of a UDP pose protocol. No sockets, no clocks.

#include <cstdint>
#include <random>
#include <vector>

#include "io/path_interpolator.h"
#include "io/pose.h"
#include "io/pose_intake.h"
#include "io/wire/pose_message.h"

namespace ig::io {

// The path at time t as a pose message numbered `sequence`: local position,
// heading / pitch / roll and the velocity over t +- half_step_s (one-sided at
// the start). `pose` and `hpr` receive what it holds.
wire::PoseMessage path_pose_message(const PathInterpolator& path, double t, double half_step_s,
                                    std::uint32_t sequence, Pose& pose, Hpr& hpr);

// m as one datagram of a UDP pose protocol (native, CIGI 3.3 host datagram
// of host frame `host_frame`, FGNetFDM); empty for the CAN formats.
std::vector<std::uint8_t> encode_pose_datagram(Protocol protocol, const wire::PoseMessage& m,
                                               std::uint32_t host_frame);

// Uniform in [0, 1) from raw 32-bit draws (std:: distributions differ between
// standard libraries; this keeps a seed's impairments the same everywhere).
struct StreamRng {
  std::mt19937 gen;
  explicit StreamRng(unsigned seed) : gen(seed) {}
  double uniform() { return gen() / 4294967296.0; }
  bool chance(double p) { return p > 0 && uniform() < p; }
};

}  // namespace ig::io
