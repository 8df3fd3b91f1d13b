// Benchmark: CAN decode cost per frame (CANaerospace decode alone, decode +
// pose assembly, the 64-byte CAN FD pose) and the pose rate a 1 kHz
// CANaerospace stream sustains through the IG's CanPoseSource, on the host
// (frames handed in with their bus timestamps; the kernel path is measured in
// the vcan VM: tools/bench/can_vm_bench.sh). Prints figures; asserts nothing.
//   build/bin/bench_can [--poses N]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "io/can/can_pose_source.h"
#include "io/wire/can_fd_pose.h"
#include "io/wire/canaerospace.h"

namespace {
using Clock = std::chrono::steady_clock;
using namespace ig::io;

wire::PoseMessage pose_at(int i) {
  wire::PoseMessage m;
  m.frame = wire::PoseMessage::Frame::Geodetic;
  m.position = {46.5 + i * 1e-6, 7.9 + i * 1e-6, 1000.0 + i * 0.01};
  m.heading_deg = (i % 3600) * 0.1;
  m.pitch_deg = 5.0;
  m.roll_deg = -10.0;
  m.body_rates_dps = {1.0, 2.0, 3.0};
  m.has_rates = true;
  m.sequence = std::uint32_t(i);
  m.has_sequence = true;
  return m;
}

double ns_since(Clock::time_point t0, double n) {
  return std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / n;
}

}  // namespace

int main(int argc, char** argv) {
  int poses = 200000;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--poses" && i + 1 < argc) poses = std::max(1000, std::atoi(argv[++i]));
    else {
      std::fprintf(stderr, "usage: bench_can [--poses N]\n");
      return 2;
    }
  }
  // Each pose as CANaerospace: 311, 312, 321, 322, 1036 H+L, 1037 H+L, 303-305.
  wire::CanAerospaceEncoder encoder;
  std::vector<wire::CanFrame> frames;
  for (int i = 0; i < poses; ++i) encoder.encode(pose_at(i), frames);
  const double per_pose = double(frames.size()) / poses;
  std::vector<wire::CanFrame> fd;
  for (int i = 0; i < poses; ++i) fd.push_back(wire::encode_can_fd_pose(pose_at(i)));

  std::printf("bench_can: %d poses, %.0f CANaerospace frames per pose (DOUBLE lat/lon, with rates)\n", poses, per_pose);
  std::printf("%-44s %12s\n", "step", "ns / frame");

  {  // decode only
    wire::CanAerospaceStats stats;
    std::uint64_t ok = 0;
    const auto t0 = Clock::now();
    for (const auto& f : frames) ok += wire::decode_canaerospace(f, stats).has_value();
    std::printf("%-44s %12.1f   (%llu accepted)\n", "CANaerospace decode", ns_since(t0, double(frames.size())),
                (unsigned long long)ok);
  }
  {  // the source's whole per-frame step: decode, assemble, pose per cycle
    can::CanPoseSourceOptions o;
    o.ifname = "bench";  // never opened: frames are handed in
    can::CanPoseSource src(o);
    std::uint64_t out = 0;
    const auto t0 = Clock::now();
    for (size_t k = 0; k < frames.size(); ++k)
      src.handle_frame(frames[k], double(k / 11) * 1e-3, [&](const wire::PoseMessage&, double, can::CanFormat) { ++out; });
    std::printf("%-44s %12.1f   (%llu poses, %.0f ns per pose)\n", "CANaerospace decode + assemble (source)",
                ns_since(t0, double(frames.size())), (unsigned long long)out, ns_since(t0, double(frames.size())) * per_pose);
  }
  {
    std::uint64_t ok = 0;
    const auto t0 = Clock::now();
    for (const auto& f : fd) ok += wire::decode_can_fd_pose(f).ok();
    std::printf("%-44s %12.1f   (%llu accepted)\n", "CAN FD pose decode (CRC-32 over 60 bytes)", ns_since(t0, double(fd.size())),
                (unsigned long long)ok);
  }

  // Pose rate from 1 kHz streams (bus time, not wall time): (a) 1000 frames/s
  // in total, the parameters round-robin; (b) every parameter at 1 kHz.
  for (int every_param : {0, 1}) {
    can::CanPoseSourceOptions o;
    o.ifname = "bench";
    can::CanPoseSource src(o);
    std::uint64_t out = 0;
    const double seconds = 10.0;
    const double frame_dt = every_param ? 1e-3 / per_pose : 1e-3;
    const size_t n = size_t(seconds / frame_dt);
    const auto t0 = Clock::now();
    for (size_t k = 0; k < n && k < frames.size(); ++k)
      src.handle_frame(frames[k], k * frame_dt, [&](const wire::PoseMessage&, double, can::CanFormat) { ++out; });
    const double cpu_s = std::chrono::duration<double>(Clock::now() - t0).count();
    const double bus_s = std::min(n, frames.size()) * frame_dt;
    std::printf("1 kHz stream, %-30s %8.1f poses/s, %.4f %% of one core\n",
                every_param ? "every parameter at 1 kHz:" : "1000 frames/s in total:", out / bus_s,
                100.0 * cpu_s / bus_s);
  }
  return 0;
}
