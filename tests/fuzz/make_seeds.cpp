// Writes a small seed corpus for the fuzz targets: make_seeds OUT_DIR
// creates OUT_DIR/{native,cigi,fgfdm,can}/seed_NN from valid encodings.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "can_frame_stream.h"
#include "io/wire/can_fd_pose.h"
#include "io/wire/canaerospace.h"
#include "io/wire/cigi.h"
#include "io/wire/cigi_entities.h"
#include "io/wire/cigi_environment.h"
#include "io/wire/fgnetfdm.h"
#include "io/wire/native.h"

namespace {

using ig::io::wire::PoseMessage;

void write(const std::filesystem::path& dir, int i, const std::uint8_t* p, std::size_t n) {
  std::filesystem::create_directories(dir);
  char name[32];
  std::snprintf(name, sizeof name, "seed_%02d", i);
  std::ofstream(dir / name, std::ios::binary).write(reinterpret_cast<const char*>(p), static_cast<std::streamsize>(n));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_seeds OUT_DIR\n");
    return 2;
  }
  const std::filesystem::path out = argv[1];
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 8; ++i) {
    PoseMessage m;
    m.frame = (i & 1) ? PoseMessage::Frame::Local : PoseMessage::Frame::Geodetic;
    m.position = (i & 1) ? glm::dvec3(u(rng) * 1e5, u(rng) * 1e5, 500 + u(rng) * 400)
                         : glm::dvec3(u(rng) * 80, u(rng) * 170, 1000 + u(rng) * 900);
    m.heading_deg = 180 + 179 * u(rng);
    m.pitch_deg = 80 * u(rng);
    m.roll_deg = 170 * u(rng);
    m.has_rates = (i & 2) != 0;
    m.body_rates_dps = {u(rng) * 10, u(rng) * 10, u(rng) * 10};
    m.has_velocity = (i & 4) != 0;
    m.velocity_mps = {u(rng) * 100, u(rng) * 100, u(rng) * 10};
    m.has_sequence = true;
    m.sequence = static_cast<std::uint32_t>(i);
    m.has_sender_time = (i & 1) == 0;
    m.sender_time_s = 100 + i;
    const auto n = ig::io::wire::encode_native(m);
    write(out / "native", i, n.data(), n.size());
    m.frame = PoseMessage::Frame::Geodetic;
    m.position = glm::dvec3(u(rng) * 80, u(rng) * 170, 1000 + u(rng) * 900);
    auto c = ig::io::wire::encode_cigi_host_datagram(static_cast<std::uint32_t>(i), 1, m, (i & 1) != 0);
    if (i % 4 == 3) {  // and the environment packets, so mutations start from them too
      using namespace ig::io::wire;
      const bool swap = (i & 1) != 0;
      auto add = [&c](const auto& packet) { c.insert(c.end(), packet.begin(), packet.end()); };
      add(encode_cigi_celestial({12, 30, true, true, false, false, true, 6, 21, 2026, 0.0f}, swap));
      add(encode_cigi_atmosphere({true, 50, 15.0f, 5000.0f, 3.0f, 0.0f, 270.0f, 1013.0f}, swap));
      add(encode_cigi_rate_control({0, 0, false, true, {50, 0, 0}, {0, 0, 3}}, swap));
      add(encode_cigi_position_request({{0, 0, kCigiObjectEntity, 0}, true}, swap));
      add(encode_cigi_collision_segment({0, 1, true, {0, 0, 0}, {0, 0, 500}, 0}, swap));
      add(encode_cigi_environment_request({kCigiConditionsWeather, 1, {36.7, -118.0, 2000.0}}, swap));
      CigiEntityControl wingman;
      wingman.entity = 2;
      wingman.type = 1;
      wingman.attached = true;
      wingman.clamp = CigiClamp::NonConformal;
      wingman.position = {-20.0, 10.0, 0.0};
      add(encode_cigi_entity_control(wingman, swap));
      CigiArticulatedPart turret;
      turret.entity = 2;
      turret.yaw_deg = 30.0f;
      add(encode_cigi_articulated_part(turret, swap));
      add(encode_cigi_rate_control({2, 0, false, false, {10, 0, 0}, {0, 0, 1}}, swap));
    }
    write(out / "cigi", i, c.data(), c.size());
    const auto f = ig::io::wire::encode_fgnetfdm(m);
    write(out / "fgfdm", i, f.data(), f.size());
    // CAN: a CANaerospace cycle (DOUBLE or FLOAT position) then an FD pose.
    ig::io::wire::CanAerospaceEncodeConfig cc;
    cc.position_as_double = (i & 1) == 0;
    ig::io::wire::CanAerospaceEncoder enc(cc);
    std::vector<std::uint8_t> stream;
    for (const auto& frame : enc.encode(m)) ig_fuzz::append_frame_bytes(stream, frame);
    ig_fuzz::append_frame_bytes(stream, ig::io::wire::encode_can_fd_pose(m));
    write(out / "can", i, stream.data(), stream.size());
  }
  return 0;
}
