#include "io/wire/native.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/wire/byte_io.h"
#include "io/wire/crc32.h"
#include "io/test/wire_test_support.h"

namespace {

using namespace ig::io::wire;
using wire_test::random_pose;

using Packet = std::array<std::uint8_t, kNativeSize>;

DecodeResult decode(const Packet& p) { return decode_native(std::span<const std::uint8_t>(p.data(), p.size())); }

void recrc(Packet& p) {
  const std::uint32_t c = crc32(std::span<const std::uint8_t>(p.data(), native_offset::kCrc));
  bytes::store_u32(p.data() + native_offset::kCrc, c, bytes::Order::Little);
}

void put_f64(Packet& p, std::size_t at, double v) {
  bytes::store_f64(p.data() + at, v, bytes::Order::Little);
  recrc(p);
}

std::string hex(std::span<const std::uint8_t> b) {
  std::string s;
  char buf[4];
  for (auto x : b) {
    std::snprintf(buf, sizeof buf, "%02x", x);
    s += buf;
  }
  return s;
}

PoseMessage sample_pose() {
  return wire_test::with_every_field(wire_test::sample_geodetic_pose({37.6189, -122.375, 120.5}), 12.5);
}

TEST(WireCrc32, CheckValue) {
  const char* s = "123456789";
  EXPECT_EQ(crc32(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(s), 9)), 0xCBF43926u);
  EXPECT_EQ(crc32({}), 0u);
  // Incremental equals one-shot.
  const auto* u = reinterpret_cast<const std::uint8_t*>(s);
  EXPECT_EQ(crc32_update(crc32_update(0, {u, 4}), {u + 4, 5}), 0xCBF43926u);
}

TEST(WireNative, LayoutOfSamplePacket) {
  const Packet p = encode_native(sample_pose());
  EXPECT_EQ(std::string(p.begin(), p.begin() + 4), "IGPS");
  EXPECT_EQ(p[4], 1);  // version 1, little-endian
  EXPECT_EQ(p[5], 0);
  EXPECT_EQ(p[6], 0x1f);  // all five flags
  EXPECT_EQ(p[8], 42);
  double lat;
  std::memcpy(&lat, &p[24], 8);  // test host is little-endian
  if constexpr (std::endian::native == std::endian::little) {
    EXPECT_EQ(lat, 37.6189);
  }
  for (std::size_t i = native_offset::kReserved1; i < native_offset::kCrc; ++i) EXPECT_EQ(p[i], 0) << i;
  // Golden bytes (also printed in docs/protocol.md): the format must not drift.
  // Cross-checked with Python: struct.pack('<4sHHIIdddddddffffff28x') + zlib.crc32.
  EXPECT_EQ(hex(p),
            "49475053" "0100" "1f00" "2a000000" "00000000"   // magic, version, flags, seq, reserved
            "0000000000002940"                                // sender time 12.5 s
            "48bf7d1d38cf4240" "0000000000985ec0" "0000000000205e40"  // lat, lon, alt
            "0000000000807140" "0000000000000c40" "00000000000024c0"  // heading, pitch, roll
            "0000803f" "000000bf" "00000040"                  // roll, pitch, yaw rate
            "000070c2" "00002041" "0000c03f"                  // velocity E, N, U
            "00000000000000000000000000000000000000000000000000000000"  // reserved
            "52207c40");                                      // CRC-32 0x407c2052
  std::printf("sample packet: %s\n", hex(p).c_str());
}

TEST(WireNative, RoundTripRandomPoses) {
  std::mt19937_64 rng(1234);
  for (int i = 0; i < 20000; ++i) {
    const PoseMessage in = random_pose(rng, (i & 1) != 0);
    const DecodeResult r = decode(encode_native(in));
    ASSERT_TRUE(r.pose) << reject_name(*r.reject);
    const PoseMessage& out = *r.pose;
    ASSERT_EQ(out.frame, in.frame);
    EXPECT_EQ(out.position, in.position);
    EXPECT_EQ(out.heading_deg, in.heading_deg);
    EXPECT_EQ(out.pitch_deg, in.pitch_deg);
    EXPECT_EQ(out.roll_deg, in.roll_deg);
    ASSERT_EQ(out.has_rates, in.has_rates);
    ASSERT_EQ(out.has_velocity, in.has_velocity);
    ASSERT_EQ(out.has_sequence, in.has_sequence);
    ASSERT_EQ(out.has_sender_time, in.has_sender_time);
    for (int k = 0; k < 3; ++k) {
      wire_test::expect_near_rel(out.body_rates_dps[k], in.body_rates_dps[k], 1e-6, 1e-5);
      wire_test::expect_near_rel(out.velocity_mps[k], in.velocity_mps[k], 1e-6, 1e-5);
    }
    EXPECT_EQ(out.sequence, in.sequence);
    EXPECT_EQ(out.sender_time_s, in.sender_time_s);
    ASSERT_FALSE(HasFailure()) << "pose " << i;
  }
}

TEST(WireNative, RejectsWrongSizes) {
  const Packet p = encode_native(sample_pose());
  std::vector<std::uint8_t> v(p.begin(), p.end());
  EXPECT_EQ(decode_native(std::span<const std::uint8_t>(v.data(), 127)).reject, Reject::TooShort);
  EXPECT_EQ(decode_native({}).reject, Reject::TooShort);
  v.push_back(0);
  EXPECT_EQ(decode_native(v).reject, Reject::TooLong);
}

TEST(WireNative, RejectsMagicVersionCrc) {
  Packet p = encode_native(sample_pose());
  Packet bad = p;
  bad[3] = '2';
  recrc(bad);
  EXPECT_EQ(decode(bad).reject, Reject::BadMagic);
  bad = p;
  bad[4] = 2;
  recrc(bad);
  EXPECT_EQ(decode(bad).reject, Reject::BadVersion);
  for (std::size_t byte : {0ul, 10ul, 30ul, 100ul, 126ul}) {
    if (byte < 6) continue;  // magic / version checked before the CRC
    bad = p;
    bad[byte] ^= 0x10;
    EXPECT_EQ(decode(bad).reject, Reject::BadCrc) << byte;
  }
  EXPECT_TRUE(decode(p).pose);
}

TEST(WireNative, RejectsNonFiniteAfterCrc) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (std::size_t at : {native_offset::kPosition, native_offset::kPosition + 8, native_offset::kPosition + 16,
                         native_offset::kAttitude, native_offset::kAttitude + 8, native_offset::kAttitude + 16,
                         native_offset::kSenderTime}) {
    Packet p = encode_native(sample_pose());
    put_f64(p, at, nan);
    EXPECT_EQ(decode(p).reject, Reject::NonFinite) << at;
    put_f64(p, at, -inf);
    EXPECT_EQ(decode(p).reject, Reject::NonFinite) << at;
  }
  Packet p = encode_native(sample_pose());
  bytes::store_f32(p.data() + native_offset::kBodyRates + 4, std::nanf(""), bytes::Order::Little);
  recrc(p);
  EXPECT_EQ(decode(p).reject, Reject::NonFinite);
  // The same NaN in a field whose flag is clear is ignored and zeroed.
  PoseMessage no_rates = sample_pose();
  no_rates.has_rates = false;
  p = encode_native(no_rates);
  bytes::store_f32(p.data() + native_offset::kBodyRates + 4, std::nanf(""), bytes::Order::Little);
  recrc(p);
  const DecodeResult r = decode(p);
  ASSERT_TRUE(r.pose);
  EXPECT_EQ(r.pose->body_rates_dps, glm::dvec3(0.0));
}

TEST(WireNative, RejectsOutOfRange) {
  auto reject_with = [](PoseMessage m) { return decode(encode_native(m)).reject; };
  PoseMessage m = sample_pose();
  m.position.x = 90.0001;
  EXPECT_EQ(reject_with(m), Reject::OutOfRange);
  m = sample_pose();
  m.position.x = -91;
  EXPECT_EQ(reject_with(m), Reject::OutOfRange);
  m = sample_pose();
  m.position.y = 360.0;
  EXPECT_EQ(reject_with(m), Reject::OutOfRange);
  m.position.y = -180.5;
  EXPECT_EQ(reject_with(m), Reject::OutOfRange);
  m = sample_pose();
  m.position.z = 1e6;
  EXPECT_EQ(reject_with(m), Reject::OutOfRange);
  m = sample_pose();
  m.heading_deg = 1.5e4;
  EXPECT_EQ(reject_with(m), Reject::OutOfRange);
  m = sample_pose();
  m.velocity_mps.x = 2e5;
  EXPECT_EQ(reject_with(m), Reject::OutOfRange);
  m = sample_pose();
  m.frame = PoseMessage::Frame::Local;
  m.position = {2e8, 0, 0};
  EXPECT_EQ(reject_with(m), Reject::OutOfRange);
  m.position = {0, 0, -1e6};
  EXPECT_EQ(reject_with(m), Reject::OutOfRange);
  m.position = {9e7, -9e7, 9e5};  // inside the local limits
  EXPECT_FALSE(reject_with(m));
}

TEST(WireNative, NormalisesAngles) {
  PoseMessage m = sample_pose();
  m.heading_deg = -90.0;
  m.pitch_deg = 100.0;  // over the top: heading and roll turn by 180
  m.roll_deg = 10.0;
  m.position.y = 200.0;  // [180, 360) folds to [-180, 180)
  const DecodeResult r = decode(encode_native(m));
  ASSERT_TRUE(r.pose);
  EXPECT_DOUBLE_EQ(r.pose->heading_deg, 90.0);
  EXPECT_DOUBLE_EQ(r.pose->pitch_deg, 80.0);
  EXPECT_DOUBLE_EQ(r.pose->roll_deg, -170.0);
  EXPECT_DOUBLE_EQ(r.pose->position.y, -160.0);
  m = sample_pose();
  m.heading_deg = 720.0 + 45.0;
  m.roll_deg = -180.0;
  const DecodeResult r2 = decode(encode_native(m));
  ASSERT_TRUE(r2.pose);
  EXPECT_DOUBLE_EQ(r2.pose->heading_deg, 45.0);
  EXPECT_DOUBLE_EQ(r2.pose->roll_deg, 180.0);
}

TEST(WireNative, RejectNamesAreDistinct) {
  const Reject all[] = {Reject::TooShort,   Reject::TooLong,   Reject::BadMagic,      Reject::BadVersion,
                        Reject::BadCrc,     Reject::NonFinite, Reject::OutOfRange,    Reject::UnknownPacket,
                        Reject::Truncated,  Reject::NoPose};
  for (Reject a : all)
    for (Reject b : all)
      if (a != b) {
        EXPECT_STRNE(reject_name(a), reject_name(b));
      }
  EXPECT_STREQ(reject_name(Reject::BadCrc), "BadCrc");
}

TEST(WireNative, EncoderToleratesGarbage) {
  PoseMessage m = sample_pose();
  m.body_rates_dps.x = 1e300;  // beyond float: written as Inf
  m.velocity_mps.y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(decode(encode_native(m)).reject, Reject::NonFinite);
  m = sample_pose();
  m.heading_deg = -1e300;
  EXPECT_EQ(decode(encode_native(m)).reject, Reject::OutOfRange);
}

// Bounded robustness run (the libFuzzer targets in tests/fuzz go further).
TEST(WireNativeRandomized, MutatedBuffersNeverYieldBadPoses) {
  std::mt19937_64 rng(777);
  std::vector<std::vector<std::uint8_t>> seeds;
  for (int i = 0; i < 32; ++i) {
    const Packet p = encode_native(random_pose(rng, (i & 1) != 0));
    seeds.emplace_back(p.begin(), p.end());
  }
  int accepted = 0, crc_rejects = 0;
  for (int i = 0; i < 200000; ++i) {
    std::vector<std::uint8_t> b = wire_test::mutate(rng, seeds[rng() % seeds.size()], 600);
    // Half the time fix the CRC so the value checks see the mutation.
    if (b.size() == kNativeSize && (rng() & 1u)) {
      const std::uint32_t c = crc32(std::span<const std::uint8_t>(b.data(), native_offset::kCrc));
      bytes::store_u32(b.data() + native_offset::kCrc, c, bytes::Order::Little);
    }
    const DecodeResult r = decode_native(b);
    wire_test::check_result(r);
    if (HasFatalFailure()) return;
    accepted += r.pose ? 1 : 0;
    crc_rejects += (r.reject == Reject::BadCrc) ? 1 : 0;
  }
  EXPECT_GT(accepted, 1000);
  EXPECT_GT(crc_rejects, 1000);
}

}  // namespace
