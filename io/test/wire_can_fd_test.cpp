// Host-side CAN FD single-frame pose codec, and bounded random and mutated
// frames through both CAN decoders. No sockets.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "io/wire/byte_io.h"
#include "io/wire/can_fd_pose.h"
#include "io/wire/can_frame.h"
#include "io/wire/canaerospace.h"
#include "io/wire/crc32.h"
#include "io/test/can_test_support.h"
#include "io/test/wire_test_support.h"

namespace {

using namespace can_test;

// ---------------------------------------------------------------------------
// CAN FD pose

void recrc(CanFrame& f) {
  const std::uint32_t c = crc32(std::span<const std::uint8_t>(f.data.data(), can_fd_offset::kCrc));
  bytes::store_u32(f.data.data() + can_fd_offset::kCrc, c, bytes::Order::Little);
}

PoseMessage full_pose() { return wire_test::with_every_field(sample_pose(), 1234.5); }

TEST(CanFdPose, LayoutAndRoundTrip) {
  const PoseMessage in = full_pose();
  const CanFrame f = encode_can_fd_pose(in);
  EXPECT_EQ(f.id, kCanFdPoseId);
  EXPECT_EQ(f.len, 64);
  EXPECT_TRUE(f.is_fd());
  EXPECT_EQ(f.data[0], 'I');
  EXPECT_EQ(f.data[1], 'F');
  EXPECT_EQ(f.data[2], 1);
  EXPECT_EQ(f.data[3], 0x1F);
  EXPECT_EQ(bytes::load_u32(f.data.data() + 4, bytes::Order::Little), 42u);
  EXPECT_EQ(bytes::load_f64(f.data.data() + 16, bytes::Order::Little), in.position.x);
  EXPECT_EQ(static_cast<std::int16_t>(bytes::load_u16(f.data.data() + 48, bytes::Order::Little)), 50);  // 1.0 / 0.02
  EXPECT_EQ(static_cast<std::int16_t>(bytes::load_u16(f.data.data() + 54, bytes::Order::Little)), -1200);
  const DecodeResult r = decode_can_fd_pose(f);
  ASSERT_TRUE(r.ok()) << reject_name(*r.reject);
  const PoseMessage& o = *r.pose;
  EXPECT_EQ(o.frame, PoseMessage::Frame::Geodetic);
  EXPECT_EQ(o.position.x, in.position.x);
  EXPECT_EQ(o.position.y, in.position.y);
  EXPECT_FLOAT_EQ(o.position.z, in.position.z);
  EXPECT_FLOAT_EQ(o.heading_deg, in.heading_deg);
  EXPECT_FLOAT_EQ(o.pitch_deg, in.pitch_deg);
  EXPECT_FLOAT_EQ(o.roll_deg, in.roll_deg);
  EXPECT_EQ(o.sequence, 42u);
  EXPECT_EQ(o.sender_time_s, 1234.5);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(o.body_rates_dps[i], in.body_rates_dps[i], 1e-9);
    EXPECT_NEAR(o.velocity_mps[i], in.velocity_mps[i], 1e-9);
  }
}

TEST(CanFdPose, RandomRoundTrips) {
  std::mt19937_64 rng(11);
  for (int k = 0; k < 5000; ++k) {
    const PoseMessage in = random_pose(rng, (k & 1) != 0);
    const DecodeResult r = decode_can_fd_pose(encode_can_fd_pose(in));
    ASSERT_TRUE(r.ok());
    const PoseMessage& o = *r.pose;
    EXPECT_EQ(o.frame, in.frame);
    EXPECT_EQ(o.position.x, in.position.x);
    EXPECT_EQ(o.position.y, in.position.y);
    wire_test::expect_near_rel(o.position.z, in.position.z, 1e-7, 1e-6);
    EXPECT_NEAR(angle_diff(o.heading_deg, in.heading_deg), 0.0, 1e-4);
    EXPECT_NEAR(o.pitch_deg, in.pitch_deg, 1e-5);
    EXPECT_NEAR(angle_diff(o.roll_deg, in.roll_deg), 0.0, 1e-4);
    EXPECT_EQ(o.has_rates, in.has_rates);
    EXPECT_EQ(o.has_velocity, in.has_velocity);
    EXPECT_EQ(o.has_sequence, in.has_sequence);
    EXPECT_EQ(o.has_sender_time, in.has_sender_time);
    if (in.has_sequence) { EXPECT_EQ(o.sequence, in.sequence); }
    if (in.has_sender_time) { EXPECT_EQ(o.sender_time_s, in.sender_time_s); }
    for (int i = 0; i < 3; ++i) {
      if (in.has_rates) { EXPECT_NEAR(o.body_rates_dps[i], in.body_rates_dps[i], kCanFdRateScale / 2 + 1e-9); }
      if (in.has_velocity) { EXPECT_NEAR(o.velocity_mps[i], in.velocity_mps[i], kCanFdVelocityScale / 2 + 1e-9); }
    }
  }
}

TEST(CanFdPose, RatesAndVelocitySaturate) {
  PoseMessage in = full_pose();
  in.body_rates_dps = {1000.0, -1000.0, 0.0};
  in.velocity_mps = {5000.0, 0.0, -5000.0};
  const DecodeResult r = decode_can_fd_pose(encode_can_fd_pose(in));
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.pose->body_rates_dps.x, 32767 * kCanFdRateScale, 1e-9);
  EXPECT_NEAR(r.pose->body_rates_dps.y, -32767 * kCanFdRateScale, 1e-9);
  EXPECT_NEAR(r.pose->velocity_mps.z, -32767 * kCanFdVelocityScale, 1e-9);
}

TEST(CanFdPose, EveryReject) {
  const CanFrame good = encode_can_fd_pose(full_pose());
  auto expect_reject = [](const CanFrame& f, Reject want) {
    const DecodeResult r = decode_can_fd_pose(f);
    wire_test::check_result(r);
    ASSERT_TRUE(r.reject.has_value());
    EXPECT_EQ(*r.reject, want) << reject_name(*r.reject);
  };
  CanFrame f = good;
  f.id = 0x7E1;
  expect_reject(f, Reject::UnknownPacket);
  f = good;
  f.flags |= kCanFlagExtended;
  expect_reject(f, Reject::UnknownPacket);
  f = good;
  f.flags = 0;  // classic frame
  expect_reject(f, Reject::TooShort);
  f = good;
  f.len = 48;
  expect_reject(f, Reject::TooShort);
  f = good;
  f.len = 65;  // not a bus length, but the struct allows the value
  expect_reject(f, Reject::TooLong);
  f = good;
  f.data[1] = 'S';
  expect_reject(f, Reject::BadMagic);
  f = good;
  f.data[2] = 2;
  expect_reject(f, Reject::BadVersion);
  f = good;
  f.data[20] ^= 0x01;
  expect_reject(f, Reject::BadCrc);
  f = good;
  f.data[63] ^= 0x80;
  expect_reject(f, Reject::BadCrc);
  f = good;
  bytes::store_f32(f.data.data() + can_fd_offset::kAttitude, std::numeric_limits<float>::quiet_NaN(),
                   bytes::Order::Little);
  recrc(f);
  expect_reject(f, Reject::NonFinite);
  f = good;
  bytes::store_f64(f.data.data() + can_fd_offset::kPositionXY, std::numeric_limits<double>::infinity(),
                   bytes::Order::Little);
  recrc(f);
  expect_reject(f, Reject::NonFinite);
  f = good;
  bytes::store_u16(f.data.data() + can_fd_offset::kVelocity + 2, 0x8000, bytes::Order::Little);  // marker
  recrc(f);
  expect_reject(f, Reject::NonFinite);
  f = good;
  bytes::store_f64(f.data.data() + can_fd_offset::kPositionXY, 91.0, bytes::Order::Little);  // lat
  recrc(f);
  expect_reject(f, Reject::OutOfRange);
  f = good;
  bytes::store_f32(f.data.data() + can_fd_offset::kPositionZ, 2e6f, bytes::Order::Little);
  recrc(f);
  expect_reject(f, Reject::OutOfRange);
  // Encoder puts NaN on the wire; the receiver rejects it.
  PoseMessage bad = full_pose();
  bad.body_rates_dps.y = std::nan("");
  expect_reject(encode_can_fd_pose(bad), Reject::NonFinite);
  bad = full_pose();
  bad.pitch_deg = std::nan("");
  expect_reject(encode_can_fd_pose(bad), Reject::NonFinite);
}

// ---------------------------------------------------------------------------
// Bounded randomized robustness: random and mutated frames never crash and
// only valid values / poses come out.

TEST(CanFuzz, RandomFramesOnlyValidOutput) {
  std::mt19937_64 rng(2024);
  static const std::uint16_t kIds[] = {303, 304, 305, 311, 312, 320, 321, 322, 332, 1036, 1037, 1038, 0x7E0, 0};
  CanAerospaceStats st;
  CanPoseConfig pc;
  pc.max_age_s = 1e9;
  CanPoseAssembler as(pc);
  CanAerospaceEncoder enc;
  const CanFrame fd_seed = encode_can_fd_pose(full_pose());
  std::vector<std::uint8_t> fd_seed_bytes(fd_seed.data.begin(), fd_seed.data.end());
  std::uint64_t values = 0, poses = 0, fd_ok = 0;
  for (int k = 0; k < 100000; ++k) {
    CanFrame f;
    const unsigned kind = static_cast<unsigned>(rng() % 4);
    if (kind == 0) {  // pure noise
      f.id = static_cast<std::uint32_t>(rng() & 0x7FF);
      f.flags = static_cast<std::uint8_t>(rng() & 0x1F);
      f.len = static_cast<std::uint8_t>(rng() % 65);
      for (auto& b : f.data) b = static_cast<std::uint8_t>(rng());
    } else if (kind == 1) {  // plausible CANaerospace frame with random fields
      f.id = kIds[rng() % (sizeof(kIds) / sizeof(kIds[0]))];
      f.len = (rng() % 8) == 0 ? static_cast<std::uint8_t>(rng() % 9) : 8;
      for (auto& b : f.data) b = static_cast<std::uint8_t>(rng());
      const std::uint8_t types[] = {kCanAsFloat, kCanAsDoubleH, kCanAsDoubleL, static_cast<std::uint8_t>(rng())};
      f.data[1] = types[rng() % 4];
    } else if (kind == 2) {  // a real encoded frame, mutated
      const auto frames = enc.encode(random_pose(rng, true));
      f = frames[rng() % frames.size()];
      std::vector<std::uint8_t> b(f.data.begin(), f.data.begin() + 8);
      b = wire_test::mutate(rng, b, 8);
      f.len = static_cast<std::uint8_t>(b.size());
      std::copy(b.begin(), b.end(), f.data.begin());
    } else {  // an FD pose, mutated
      f = fd_seed;
      auto b = wire_test::mutate(rng, fd_seed_bytes, 64);
      f.len = static_cast<std::uint8_t>(b.size());
      std::copy(b.begin(), b.end(), f.data.begin());
      if (rng() % 4 == 0) recrc(f);
    }
    if (f.id == kCanFdPoseId) {
      const DecodeResult r = decode_can_fd_pose(f);
      wire_test::check_result(r);
      if (r.ok()) ++fd_ok;
      continue;
    }
    if (auto v = decode_canaerospace(f, st)) {
      ++values;
      ASSERT_GE(canaerospace_id_index(v->id), 0);
      if (v->data_type == kCanAsFloat) { ASSERT_TRUE(std::isfinite(v->value)); }
      as.feed(*v, static_cast<double>(k));
    }
    if (k % 16 == 0) {
      StaleFields sf;
      if (auto p = as.pose(static_cast<double>(k), sf)) {
        ++poses;
        ASSERT_TRUE(is_valid_output(*p));
      }
    }
  }
  EXPECT_EQ(st.frames, st.accepted + st.rejected());
  EXPECT_GT(values, 1000u);
  EXPECT_GT(poses, 0u);
  EXPECT_GT(fd_ok, 0u);
}

}  // namespace
