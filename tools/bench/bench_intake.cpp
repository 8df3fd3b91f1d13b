// Benchmark: decode cost per packet for each pose protocol, and the cost of
// the whole intake step (decode + geodetic placement + pose filter push).
// Prints figures; asserts nothing.   build/bin/bench_intake [--packets N]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "io/filter/geodesy.h"
#include "io/pose_intake.h"
#include "io/wire/cigi.h"
#include "io/wire/fgnetfdm.h"
#include "io/wire/native.h"

namespace {
using Clock = std::chrono::steady_clock;

std::vector<std::vector<std::uint8_t>> make_packets(ig::io::Protocol p, int n) {
  std::vector<std::vector<std::uint8_t>> out;
  for (int i = 0; i < n; ++i) {
    ig::io::wire::PoseMessage m;
    m.frame = ig::io::wire::PoseMessage::Frame::Geodetic;
    m.position = {46.5 + i * 1e-5, 7.9 + i * 1e-5, 1000.0 + i * 0.1};
    m.heading_deg = (i * 0.7) - 360.0 * int(i * 0.7 / 360.0);
    m.pitch_deg = 5.0;
    m.roll_deg = -10.0;
    m.sequence = std::uint32_t(i);
    m.has_sequence = true;
    m.sender_time_s = i / 60.0;
    m.has_sender_time = true;
    m.velocity_mps = {100, 50, 0};
    m.has_velocity = true;
    switch (p) {
      case ig::io::Protocol::Native: {
        const auto a = ig::io::wire::encode_native(m);
        out.emplace_back(a.begin(), a.end());
        break;
      }
      case ig::io::Protocol::Cigi: out.push_back(ig::io::wire::encode_cigi_host_datagram(std::uint32_t(i), 1, m, false)); break;
      case ig::io::Protocol::FgNetFdm: {
        const auto a = ig::io::wire::encode_fgnetfdm(m);
        out.emplace_back(a.begin(), a.end());
        break;
      }
      default: break;  // CAN formats: bench_can
    }
  }
  return out;
}
}  // namespace

int main(int argc, char** argv) {
  int n = 1000000;
  for (int k = 1; k + 1 < argc; ++k)
    if (std::string(argv[k]) == "--packets") n = std::max(1000, std::atoi(argv[k + 1]));
  const auto grid = ig::io::geo::GeographicGrid::make({7.9, 1.0 / 2300.0, 0, 46.5, 0, 1.0 / 3700.0}, 30.0, 30.0);
  std::printf("%-8s %8s %16s %22s\n", "protocol", "bytes", "decode ns/packet", "intake ns/packet (all)");
  for (auto p : {ig::io::Protocol::Native, ig::io::Protocol::Cigi, ig::io::Protocol::FgNetFdm}) {
    const auto packets = make_packets(p, 4096);
    std::uint64_t accepted = 0;
    auto t0 = Clock::now();
    for (int i = 0; i < n; ++i) {
      const auto& b = packets[size_t(i) & 4095];
      switch (p) {
        case ig::io::Protocol::Native: accepted += ig::io::wire::decode_native(b).ok(); break;
        case ig::io::Protocol::Cigi: accepted += ig::io::wire::decode_cigi_host_datagram(b).ok(); break;
        case ig::io::Protocol::FgNetFdm: accepted += ig::io::wire::decode_fgnetfdm(b).ok(); break;
        default: break;  // CAN formats: bench_can
      }
    }
    const double decode_ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / n;

    // The whole intake step for a 60 Hz stream's worth of packets (fresh filter per 4096).
    const int m = std::min(n, 200000);
    double intake_ns = 0;
    for (int done = 0; done < m; done += 4096) {
      ig::io::PoseFilter filter;
      ig::io::PoseIntake intake(filter, [&](double lat, double lon, double alt) {
        return std::optional<glm::dvec3>(glm::dvec3(grid->to_local(lat, lon), alt));
      });
      t0 = Clock::now();
      for (int i = 0; i < 4096; ++i) intake.handle(p, packets[size_t(i)], i / 60.0);
      intake_ns += std::chrono::duration<double, std::nano>(Clock::now() - t0).count();
      accepted += intake.total_ok();
    }
    std::printf("%-8s %8zu %16.1f %22.1f\n", ig::io::protocol_name(p), packets[0].size(), decode_ns,
                intake_ns / ((m + 4095) / 4096 * 4096));
    if (accepted == 0) std::printf("(nothing accepted?)\n");
  }
  return 0;
}
