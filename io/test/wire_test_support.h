#pragma once
// Shared helpers for the wire_*_test.cpp binaries (header only).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/wire/pose_message.h"

namespace wire_test {

using ig::io::wire::PoseMessage;

inline double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// A random pose in normalised ranges (kept a hair away from the wrap points
// so f32 rounding cannot move a value across them).
inline PoseMessage random_pose(std::mt19937_64& rng, bool geodetic) {
  PoseMessage m;
  m.frame = geodetic ? PoseMessage::Frame::Geodetic : PoseMessage::Frame::Local;
  if (geodetic) {
    m.position = {uniform(rng, -90.0, 90.0), uniform(rng, -180.0, 179.999), uniform(rng, -500.0, 20000.0)};
  } else {
    m.position = {uniform(rng, -5e7, 5e7), uniform(rng, -5e7, 5e7), uniform(rng, -1e4, 1e5)};
  }
  m.heading_deg = uniform(rng, 0.0, 359.999);
  m.pitch_deg = uniform(rng, -89.999, 89.999);
  m.roll_deg = uniform(rng, -179.999, 179.999);
  m.has_rates = (rng() & 1u) != 0;
  m.has_velocity = (rng() & 2u) != 0;
  if (m.has_rates) m.body_rates_dps = {uniform(rng, -300, 300), uniform(rng, -300, 300), uniform(rng, -300, 300)};
  if (m.has_velocity) m.velocity_mps = {uniform(rng, -400, 400), uniform(rng, -400, 400), uniform(rng, -100, 100)};
  m.has_sequence = (rng() & 4u) != 0;
  if (m.has_sequence) m.sequence = static_cast<std::uint32_t>(rng());
  m.has_sender_time = (rng() & 8u) != 0;
  if (m.has_sender_time) m.sender_time_s = uniform(rng, 0.0, 40000.0);
  return m;
}

// A geodetic pose at `position` (lat, lon, alt) with a fixed attitude and
// body rates, the codec tests' worked example.
inline PoseMessage sample_geodetic_pose(const glm::dvec3& position) {
  PoseMessage m;
  m.frame = PoseMessage::Frame::Geodetic;
  m.position = position;
  m.heading_deg = 280.0;
  m.pitch_deg = 3.5;
  m.roll_deg = -10.0;
  m.has_rates = true;
  m.body_rates_dps = {1.0, -0.5, 2.0};
  return m;
}

// m with every optional field set: velocity, sequence 42 and sender time.
inline PoseMessage with_every_field(PoseMessage m, double sender_time_s) {
  m.has_velocity = true;
  m.velocity_mps = {-60.0, 10.0, 1.5};
  m.has_sequence = true;
  m.sequence = 42;
  m.has_sender_time = true;
  m.sender_time_s = sender_time_s;
  return m;
}

// Smallest signed difference between two angles, degrees.
inline double angle_diff(double a, double b) {
  double d = std::fmod(a - b, 360.0);
  if (d > 180.0) d -= 360.0;
  if (d < -180.0) d += 360.0;
  return d;
}

inline void expect_near_rel(double got, double want, double rel, double abs_tol = 1e-9) {
  EXPECT_NEAR(got, want, std::max(abs_tol, rel * std::fabs(want)));
}

// A random mutation of `seed`: bit flips, byte stores, special floats,
// truncation / extension, or pure noise; sizes stay within [0, max_size].
inline std::vector<std::uint8_t> mutate(std::mt19937_64& rng, const std::vector<std::uint8_t>& seed,
                                        std::size_t max_size) {
  std::vector<std::uint8_t> b = seed;
  const unsigned kind = static_cast<unsigned>(rng() % 10);
  if (kind == 0) {  // pure noise of random size
    b.resize(rng() % (max_size + 1));
    for (auto& x : b) x = static_cast<std::uint8_t>(rng());
    return b;
  }
  if (kind == 1 || kind == 2) {  // resize: cut or extend
    const std::size_t n = rng() % (max_size + 1);
    const std::size_t old = b.size();
    b.resize(n);
    for (std::size_t i = old; i < n; ++i) b[i] = static_cast<std::uint8_t>(rng());
  }
  if (b.empty()) return b;
  const int flips = static_cast<int>(rng() % 9);
  for (int i = 0; i < flips; ++i) b[rng() % b.size()] ^= static_cast<std::uint8_t>(1u << (rng() % 8));
  if (kind == 3 || kind == 4) {  // drop a special value at a random offset
    static const double specials[] = {std::nan(""), INFINITY, -INFINITY, 1e300, -1e300, 1e-310, 91.0,
                                      -181.0, 360.0, 1e4, 1e6, 1e8, 0.0, -0.0};
    const double v = specials[rng() % (sizeof(specials) / sizeof(specials[0]))];
    if ((rng() & 1u) && b.size() >= 8) {
      const std::size_t at = rng() % (b.size() - 7);
      std::memcpy(&b[at], &v, 8);
      if (rng() & 1u) std::reverse(b.begin() + at, b.begin() + at + 8);
    } else if (b.size() >= 4) {
      const float f = static_cast<float>(v);
      const std::size_t at = rng() % (b.size() - 3);
      std::memcpy(&b[at], &f, 4);
      if (rng() & 1u) std::reverse(b.begin() + at, b.begin() + at + 4);
    }
  }
  if (kind == 5) b[rng() % b.size()] = static_cast<std::uint8_t>(rng());
  return b;
}

// Invariants of any decoder result.
inline void check_result(const ig::io::wire::DecodeResult& r) {
  ASSERT_NE(r.pose.has_value(), r.reject.has_value());
  if (r.pose) {
    ASSERT_TRUE(ig::io::wire::is_valid_output(*r.pose))
        << "lat/x " << r.pose->position.x << " lon/y " << r.pose->position.y << " alt/z " << r.pose->position.z
        << " hpr " << r.pose->heading_deg << " " << r.pose->pitch_deg << " " << r.pose->roll_deg;
  } else {
    ASSERT_NE(std::string(ig::io::wire::reject_name(*r.reject)), "Unknown");
  }
}

}  // namespace wire_test
