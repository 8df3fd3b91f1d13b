#include "io/wire/fgnetfdm.h"

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "io/test/wire_test_support.h"

namespace {

using namespace ig::io::wire;
using wire_test::angle_diff;
using wire_test::random_pose;
using Bytes = std::vector<std::uint8_t>;
namespace off = fgfdm_offset;

constexpr double kPi = 3.14159265358979323846;

// Hand-written big-endian writers, independent of io/wire/byte_io.h.
void be(Bytes& b, std::size_t at, std::uint64_t v, int n) {
  for (int i = 0; i < n; ++i) b[at + i] = static_cast<std::uint8_t>(v >> (8 * (n - 1 - i)));
}
void be_f64(Bytes& b, std::size_t at, double v) { be(b, at, std::bit_cast<std::uint64_t>(v), 8); }
void be_f32(Bytes& b, std::size_t at, float v) { be(b, at, std::bit_cast<std::uint32_t>(v), 4); }

// What FlightGear sends (all fields in network order).
Bytes handmade() {
  Bytes b(408, 0);
  be(b, 0, 24, 4);
  be_f64(b, 8, -122.375 * kPi / 180.0);  // longitude first
  be_f64(b, 16, 37.625 * kPi / 180.0);
  be_f64(b, 24, 150.0);
  be_f32(b, 32, 140.0f);                      // agl
  be_f32(b, 36, static_cast<float>(-0.25));   // phi (roll)
  be_f32(b, 40, static_cast<float>(0.125));   // theta (pitch)
  be_f32(b, 44, static_cast<float>(1.5 * kPi));  // psi: 270 deg
  be_f32(b, 56, 0.5f);   // phidot
  be_f32(b, 60, -0.25f); // thetadot
  be_f32(b, 64, 0.125f); // psidot
  be_f32(b, 68, 120.0f); // vcas
  be_f32(b, 76, 100.0f); // v_north ft/s
  be_f32(b, 80, -50.0f); // v_east
  be_f32(b, 84, 10.0f);  // v_down
  be(b, 120, 1, 4);      // one engine
  return b;
}

TEST(WireFgFdm, DecodesHandmadeFlightGearPacket) {
  const DecodeResult r = decode_fgnetfdm(handmade());
  ASSERT_TRUE(r.pose) << reject_name(*r.reject);
  const PoseMessage& m = *r.pose;
  EXPECT_EQ(m.frame, PoseMessage::Frame::Geodetic);
  EXPECT_NEAR(m.position.x, 37.625, 1e-12);    // latitude
  EXPECT_NEAR(m.position.y, -122.375, 1e-12);  // longitude
  EXPECT_EQ(m.position.z, 150.0);
  EXPECT_NEAR(m.roll_deg, -0.25 * 180 / kPi, 1e-5);
  EXPECT_NEAR(m.pitch_deg, 0.125 * 180 / kPi, 1e-5);
  EXPECT_NEAR(m.heading_deg, 270.0, 1e-4);
  ASSERT_TRUE(m.has_rates);
  EXPECT_NEAR(m.body_rates_dps.x, 0.5 * 180 / kPi, 1e-9);
  EXPECT_NEAR(m.body_rates_dps.y, -0.25 * 180 / kPi, 1e-9);
  EXPECT_NEAR(m.body_rates_dps.z, 0.125 * 180 / kPi, 1e-9);
  ASSERT_TRUE(m.has_velocity);
  EXPECT_NEAR(m.velocity_mps.x, -50 * 0.3048, 1e-9);  // east
  EXPECT_NEAR(m.velocity_mps.y, 100 * 0.3048, 1e-9);  // north
  EXPECT_NEAR(m.velocity_mps.z, -10 * 0.3048, 1e-9);  // up = -down
  EXPECT_FALSE(m.has_sequence);
  EXPECT_FALSE(m.has_sender_time);
}

TEST(WireFgFdm, EncoderLayout) {
  PoseMessage m;
  m.frame = PoseMessage::Frame::Geodetic;
  m.position = {10.0, 20.0, 30.0};
  m.has_velocity = true;
  m.velocity_mps = {3.048, 0, -0.3048};
  const auto b = encode_fgnetfdm(m);
  EXPECT_EQ(b[0], 0);
  EXPECT_EQ(b[3], 24);
  // Longitude (20 deg) at 8, big-endian.
  std::uint64_t lon_bits = 0;
  for (int i = 0; i < 8; ++i) lon_bits = (lon_bits << 8) | b[8 + i];
  EXPECT_NEAR(std::bit_cast<double>(lon_bits), 20.0 * kPi / 180.0, 1e-15);
  std::uint32_t ve_bits = 0, vd_bits = 0;
  for (int i = 0; i < 4; ++i) ve_bits = (ve_bits << 8) | b[80 + i];
  for (int i = 0; i < 4; ++i) vd_bits = (vd_bits << 8) | b[84 + i];
  EXPECT_NEAR(std::bit_cast<float>(ve_bits), 10.0f, 1e-5);
  EXPECT_NEAR(std::bit_cast<float>(vd_bits), 1.0f, 1e-6);
}

TEST(WireFgFdm, RoundTripRandomPoses) {
  std::mt19937_64 rng(31337);
  for (int i = 0; i < 20000; ++i) {
    PoseMessage in = random_pose(rng, true);
    const DecodeResult r = decode_fgnetfdm(encode_fgnetfdm(in));
    ASSERT_TRUE(r.pose) << reject_name(*r.reject);
    const PoseMessage& out = *r.pose;
    EXPECT_NEAR(out.position.x, in.position.x, 1e-9);
    EXPECT_NEAR(angle_diff(out.position.y, in.position.y), 0.0, 1e-9);
    EXPECT_EQ(out.position.z, in.position.z);
    EXPECT_NEAR(angle_diff(out.heading_deg, in.heading_deg), 0.0, 1e-4);
    EXPECT_NEAR(out.pitch_deg, in.pitch_deg, 1e-4);
    EXPECT_NEAR(angle_diff(out.roll_deg, in.roll_deg), 0.0, 1e-4);
    for (int k = 0; k < 3; ++k) {
      wire_test::expect_near_rel(out.body_rates_dps[k], in.body_rates_dps[k], 1e-6, 1e-5);
      wire_test::expect_near_rel(out.velocity_mps[k], in.velocity_mps[k], 1e-6, 1e-5);
    }
    ASSERT_FALSE(HasFailure()) << "pose " << i;
  }
}

TEST(WireFgFdm, Rejects) {
  const Bytes good = handmade();
  EXPECT_EQ(decode_fgnetfdm(std::span<const std::uint8_t>(good.data(), 407)).reject, Reject::TooShort);
  EXPECT_EQ(decode_fgnetfdm({}).reject, Reject::TooShort);
  Bytes longer = good;
  longer.push_back(0);
  EXPECT_EQ(decode_fgnetfdm(longer).reject, Reject::TooLong);
  Bytes x = good;
  be(x, 0, 25, 4);
  EXPECT_EQ(decode_fgnetfdm(x).reject, Reject::BadVersion);
  x = good;
  x[0] = 24;  // little-endian sender: 0x18000000
  x[3] = 0;
  EXPECT_EQ(decode_fgnetfdm(x).reject, Reject::BadVersion);

  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t at : {off::kLongitude, off::kLatitude, off::kAltitude}) {
    x = good;
    be_f64(x, at, nan);
    EXPECT_EQ(decode_fgnetfdm(x).reject, Reject::NonFinite) << at;
    be_f64(x, at, INFINITY);
    EXPECT_EQ(decode_fgnetfdm(x).reject, Reject::NonFinite) << at;
  }
  for (std::size_t at : {off::kPhi, off::kTheta, off::kPsi, off::kPhiDot, off::kThetaDot, off::kPsiDot,
                         off::kVNorth, off::kVEast, off::kVDown}) {
    x = good;
    be_f32(x, at, std::nanf(""));
    EXPECT_EQ(decode_fgnetfdm(x).reject, Reject::NonFinite) << at;
    be_f32(x, at, -INFINITY);
    EXPECT_EQ(decode_fgnetfdm(x).reject, Reject::NonFinite) << at;
  }
  // Unused fields may hold anything.
  x = good;
  be_f32(x, off::kAlpha, std::nanf(""));
  be_f32(x, off::kVcas, INFINITY);
  EXPECT_TRUE(decode_fgnetfdm(x).pose);

  x = good;
  be_f64(x, off::kLatitude, 91.0 * kPi / 180.0);
  EXPECT_EQ(decode_fgnetfdm(x).reject, Reject::OutOfRange);
  x = good;
  be_f64(x, off::kLongitude, -3.2);  // < -180 deg
  EXPECT_EQ(decode_fgnetfdm(x).reject, Reject::OutOfRange);
  x = good;
  be_f64(x, off::kLongitude, 1e300);  // would overflow when scaled to degrees
  EXPECT_EQ(decode_fgnetfdm(x).reject, Reject::OutOfRange);
  x = good;
  be_f64(x, off::kAltitude, -2e6);
  EXPECT_EQ(decode_fgnetfdm(x).reject, Reject::OutOfRange);
  x = good;
  be_f32(x, off::kPsi, 1e3f);  // 57000 deg
  EXPECT_EQ(decode_fgnetfdm(x).reject, Reject::OutOfRange);
  x = good;
  be_f32(x, off::kVNorth, 1e6f);
  EXPECT_EQ(decode_fgnetfdm(x).reject, Reject::OutOfRange);
  // The poles survive a sender's own degree/radian rounding.
  x = good;
  be_f64(x, off::kLatitude, std::nextafter(kPi / 2, 4.0));
  ASSERT_TRUE(decode_fgnetfdm(x).pose);
  EXPECT_EQ(decode_fgnetfdm(x).pose->position.x, 90.0);
  x = good;
  be_f64(x, off::kLatitude, -std::nextafter(kPi / 2, 4.0));
  ASSERT_TRUE(decode_fgnetfdm(x).pose);
  EXPECT_EQ(decode_fgnetfdm(x).pose->position.x, -90.0);
  // Longitude in [180, 360) deg is accepted and folded.
  x = good;
  be_f64(x, off::kLongitude, 1.5 * kPi);
  const DecodeResult r = decode_fgnetfdm(x);
  ASSERT_TRUE(r.pose);
  EXPECT_NEAR(r.pose->position.y, -90.0, 1e-12);
}

TEST(WireFgFdm, EncoderToleratesGarbage) {
  PoseMessage m;
  m.frame = PoseMessage::Frame::Geodetic;
  m.pitch_deg = 1e300;  // beyond float: written as Inf
  m.has_velocity = true;
  m.velocity_mps = {1e300, -1e300, 0};
  m.has_sender_time = true;
  m.sender_time_s = 1e300;
  EXPECT_EQ(decode_fgnetfdm(encode_fgnetfdm(m)).reject, Reject::NonFinite);
  m.pitch_deg = 0;
  m.velocity_mps = {0, 0, 0};
  m.position = {100.0, 0, 0};
  EXPECT_EQ(decode_fgnetfdm(encode_fgnetfdm(m)).reject, Reject::OutOfRange);
}

TEST(WireFgFdmRandomized, MutatedPacketsNeverYieldBadPoses) {
  std::mt19937_64 rng(2024);
  std::vector<Bytes> seeds{handmade()};
  for (int i = 0; i < 31; ++i) {
    const auto p = encode_fgnetfdm(random_pose(rng, true));
    seeds.emplace_back(p.begin(), p.end());
  }
  int accepted = 0;
  for (int i = 0; i < 200000; ++i) {
    const Bytes b = wire_test::mutate(rng, seeds[rng() % seeds.size()], 600);
    const DecodeResult r = decode_fgnetfdm(b);
    wire_test::check_result(r);
    if (HasFatalFailure()) return;
    accepted += r.pose ? 1 : 0;
  }
  EXPECT_GT(accepted, 1000);
}

}  // namespace
