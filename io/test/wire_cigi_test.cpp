#include "io/wire/cigi.h"

#include <bit>
#include <cmath>
#include <cstring>
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

// Hand-written serialisers, independent of io/wire/byte_io.h.
void be(Bytes& b, std::size_t at, std::uint64_t v, int n) {
  for (int i = 0; i < n; ++i) b[at + i] = static_cast<std::uint8_t>(v >> (8 * (n - 1 - i)));
}
void le(Bytes& b, std::size_t at, std::uint64_t v, int n) {
  for (int i = 0; i < n; ++i) b[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}

// IG Control + Entity Control as a big- or little-endian sender writes them.
Bytes handmade(bool big, std::uint16_t entity, double lat, double lon, double alt, float roll, float pitch,
               float yaw) {
  Bytes b(72, 0);
  auto put = [&](std::size_t at, std::uint64_t v, int n) { big ? be(b, at, v, n) : le(b, at, v, n); };
  b[0] = 1;
  b[1] = 24;
  b[2] = 3;
  b[4] = 0x31;  // operate, minor version 3, timestamp not valid
  put(6, 0x8000, 2);
  put(8, 0x01020304, 4);
  b[24] = 2;
  b[25] = 48;
  put(26, entity, 2);
  b[28] = 1;
  put(36, std::bit_cast<std::uint32_t>(roll), 4);
  put(40, std::bit_cast<std::uint32_t>(pitch), 4);
  put(44, std::bit_cast<std::uint32_t>(yaw), 4);
  put(48, std::bit_cast<std::uint64_t>(lat), 8);
  put(56, std::bit_cast<std::uint64_t>(lon), 8);
  put(64, std::bit_cast<std::uint64_t>(alt), 8);
  return b;
}

PoseMessage sample_pose() {
  PoseMessage m;
  m.frame = PoseMessage::Frame::Geodetic;
  m.position = {-33.9461, 151.1772, 6.0};
  m.heading_deg = 160.0;
  m.pitch_deg = -2.0;
  m.roll_deg = 15.0;
  return m;
}

TEST(WireCigi, HandmadeBigAndLittleEndianDatagrams) {
  for (bool big : {true, false}) {
    const Bytes b = handmade(big, 0, 47.25, -122.5, 1234.5, 5.0f, -3.0f, 270.0f);
    const DecodeResult r = decode_cigi_host_datagram(b);
    ASSERT_TRUE(r.pose) << reject_name(*r.reject);
    EXPECT_EQ(r.pose->frame, PoseMessage::Frame::Geodetic);
    EXPECT_EQ(r.pose->position, glm::dvec3(47.25, -122.5, 1234.5));
    EXPECT_EQ(r.pose->roll_deg, 5.0);
    EXPECT_EQ(r.pose->pitch_deg, -3.0);
    EXPECT_EQ(r.pose->heading_deg, 270.0);
    EXPECT_EQ(r.pose->host_frame, 0x01020304u);
    EXPECT_EQ(r.pose->sequence, 0x01020304u);
    EXPECT_TRUE(r.pose->has_sequence);
    EXPECT_FALSE(r.pose->has_sender_time);
    EXPECT_EQ(r.host_frame, 0x01020304u);
    EXPECT_EQ(r.ig_mode, 1u);
    EXPECT_EQ(r.byte_swapped, big == (std::endian::native == std::endian::little));
  }
}

TEST(WireCigi, EncoderWritesNativeOrderMagic) {
  for (bool swap : {false, true}) {
    const Bytes b = encode_cigi_host_datagram(7, kCigiModeOperate, sample_pose(), swap);
    ASSERT_EQ(b.size(), 72u);
    EXPECT_EQ(b[0], 1);
    EXPECT_EQ(b[1], 24);
    EXPECT_EQ(b[2], 3);
    EXPECT_EQ(b[4] >> 4, 3);  // minor version 3
    EXPECT_EQ(b[24], 2);
    EXPECT_EQ(b[25], 48);
    std::uint16_t magic;
    std::memcpy(&magic, &b[6], 2);  // read in this machine's order
    EXPECT_EQ(magic, swap ? 0x0080 : 0x8000);
    std::uint32_t frame;
    std::memcpy(&frame, &b[8], 4);
    EXPECT_EQ(frame, swap ? 0x07000000u : 7u);
  }
}

TEST(WireCigi, RoundTripRandomPosesBothByteOrders) {
  std::mt19937_64 rng(99);
  for (int i = 0; i < 20000; ++i) {
    PoseMessage in = random_pose(rng, true);
    const bool swap = (i & 1) != 0;
    const std::uint32_t frame = static_cast<std::uint32_t>(rng());
    const std::uint32_t mode = static_cast<std::uint32_t>(rng() % 3);
    const DecodeResult r = decode_cigi_host_datagram(encode_cigi_host_datagram(frame, mode, in, swap));
    ASSERT_TRUE(r.pose) << reject_name(*r.reject);
    const PoseMessage& out = *r.pose;
    EXPECT_EQ(r.byte_swapped, swap);
    EXPECT_EQ(r.host_frame, frame);
    EXPECT_EQ(r.ig_mode, mode);
    EXPECT_EQ(out.host_frame, frame);
    EXPECT_EQ(out.position, in.position);
    EXPECT_NEAR(angle_diff(out.heading_deg, in.heading_deg), 0.0, 1e-4);
    EXPECT_NEAR(out.pitch_deg, in.pitch_deg, 1e-5);
    EXPECT_NEAR(angle_diff(out.roll_deg, in.roll_deg), 0.0, 1e-4);
    EXPECT_FALSE(out.has_rates);
    EXPECT_FALSE(out.has_velocity);
    ASSERT_EQ(out.has_sender_time, in.has_sender_time);
    if (in.has_sender_time) {
      EXPECT_NEAR(out.sender_time_s, in.sender_time_s, 5.01e-6);
    }
    ASSERT_FALSE(HasFailure()) << "pose " << i;
  }
}

TEST(WireCigi, SkipsUnknownPacketsAndPicksOwnship) {
  Bytes b = encode_cigi_host_datagram(11, kCigiModeOperate, sample_pose(), false);
  // Unknown opcode 200 (16 bytes) and an Entity Control for entity 5 ahead
  // of the ownship packet.
  Bytes unknown(16, 0xEE);
  unknown[0] = 200;
  unknown[1] = 16;
  Bytes other = handmade(std::endian::native == std::endian::big, 5, 1.0, 2.0, 3.0, 0, 0, 0);
  Bytes d(b.begin(), b.begin() + 24);
  d.insert(d.end(), unknown.begin(), unknown.end());
  d.insert(d.end(), other.begin() + 24, other.end());
  d.insert(d.end(), b.begin() + 24, b.end());
  const DecodeResult r = decode_cigi_host_datagram(d);
  ASSERT_TRUE(r.pose) << reject_name(*r.reject);
  EXPECT_EQ(r.pose->position, sample_pose().position);
}

TEST(WireCigi, TruncatedAndZeroSizePackets) {
  const Bytes b = encode_cigi_host_datagram(1, 1, sample_pose(), false);
  Bytes cut(b.begin(), b.end() - 8);  // Entity Control says 48, 40 remain
  EXPECT_EQ(decode_cigi_host_datagram(cut).reject, Reject::Truncated);
  Bytes one(b.begin(), b.begin() + 25);  // a lone opcode byte
  EXPECT_EQ(decode_cigi_host_datagram(one).reject, Reject::Truncated);
  Bytes zero = b;
  zero[25] = 0;
  EXPECT_EQ(decode_cigi_host_datagram(zero).reject, Reject::Truncated);
  Bytes unknown_zero(b.begin(), b.begin() + 24);
  unknown_zero.insert(unknown_zero.end(), {77, 0, 0, 0, 0, 0, 0, 0});
  EXPECT_EQ(decode_cigi_host_datagram(unknown_zero).reject, Reject::Truncated);
  Bytes small_ec = b;
  small_ec[25] = 40;  // Entity Control must be 48 bytes
  small_ec.resize(64);
  EXPECT_EQ(decode_cigi_host_datagram(small_ec).reject, Reject::Truncated);
  Bytes zero_ig = b;
  zero_ig[1] = 0;
  EXPECT_EQ(decode_cigi_host_datagram(zero_ig).reject, Reject::Truncated);
}

TEST(WireCigi, NoPoseStillReportsIgControl) {
  Bytes b = handmade(true, 1, 10.0, 20.0, 30.0, 0, 0, 0);
  b[4] = 0x32;  // debug mode
  DecodeResult r = decode_cigi_host_datagram(b);
  EXPECT_EQ(r.reject, Reject::NoPose);
  EXPECT_FALSE(r.pose);
  EXPECT_EQ(r.host_frame, 0x01020304u);
  EXPECT_EQ(r.ig_mode, 2u);
  // IG Control alone.
  r = decode_cigi_host_datagram(std::span<const std::uint8_t>(b.data(), 24));
  EXPECT_EQ(r.reject, Reject::NoPose);
  EXPECT_EQ(r.host_frame, 0x01020304u);
  // Ownship attached to a parent: its position is relative, not geodetic.
  Bytes att = handmade(true, 0, 10.0, 20.0, 30.0, 0, 0, 0);
  att[28] |= 0x04;
  EXPECT_EQ(decode_cigi_host_datagram(att).reject, Reject::NoPose);
}

TEST(WireCigi, HeaderRejects) {
  const Bytes b = encode_cigi_host_datagram(1, 1, sample_pose(), false);
  EXPECT_EQ(decode_cigi_host_datagram({}).reject, Reject::TooShort);
  EXPECT_EQ(decode_cigi_host_datagram(std::span<const std::uint8_t>(b.data(), 23)).reject, Reject::TooShort);
  Bytes huge(70000, 0);
  std::copy(b.begin(), b.end(), huge.begin());
  EXPECT_EQ(decode_cigi_host_datagram(huge).reject, Reject::TooLong);
  Bytes x = b;
  x[0] = 2;  // does not start with IG Control
  EXPECT_EQ(decode_cigi_host_datagram(x).reject, Reject::UnknownPacket);
  x = b;
  x[2] = 4;
  EXPECT_EQ(decode_cigi_host_datagram(x).reject, Reject::BadVersion);
  x = b;
  x[1] = 16;  // CIGI 3.0/3.1 IG Control size
  EXPECT_EQ(decode_cigi_host_datagram(x).reject, Reject::BadVersion);
  x = b;
  x[6] = 0x12;
  x[7] = 0x34;
  EXPECT_EQ(decode_cigi_host_datagram(x).reject, Reject::BadMagic);
  x = b;
  x[6] = 0x80;
  x[7] = 0x80;
  EXPECT_EQ(decode_cigi_host_datagram(x).reject, Reject::BadMagic);
}

TEST(WireCigi, ValueRejects) {
  const float fnan = std::numeric_limits<float>::quiet_NaN();
  const bool big = std::endian::native == std::endian::big;
  EXPECT_EQ(decode_cigi_host_datagram(handmade(big, 0, 1, 2, 3, fnan, 0, 0)).reject, Reject::NonFinite);
  EXPECT_EQ(decode_cigi_host_datagram(handmade(!big, 0, 1, 2, 3, 0, 0, INFINITY)).reject, Reject::NonFinite);
  EXPECT_EQ(decode_cigi_host_datagram(handmade(big, 0, NAN, 2, 3, 0, 0, 0)).reject, Reject::NonFinite);
  EXPECT_EQ(decode_cigi_host_datagram(handmade(big, 0, 1, 2, INFINITY, 0, 0, 0)).reject, Reject::NonFinite);
  EXPECT_EQ(decode_cigi_host_datagram(handmade(big, 0, 90.5, 2, 3, 0, 0, 0)).reject, Reject::OutOfRange);
  EXPECT_EQ(decode_cigi_host_datagram(handmade(!big, 0, 1, 360.0, 3, 0, 0, 0)).reject, Reject::OutOfRange);
  EXPECT_EQ(decode_cigi_host_datagram(handmade(big, 0, 1, 2, 2e6, 0, 0, 0)).reject, Reject::OutOfRange);
  EXPECT_EQ(decode_cigi_host_datagram(handmade(big, 0, 1, 2, 3, 0, 3e4f, 0)).reject, Reject::OutOfRange);
  // Normalised: yaw 360 -> 0, lon 190 -> -170.
  const DecodeResult r = decode_cigi_host_datagram(handmade(big, 0, 1, 190.0, 3, 0, 0, 360.0f));
  ASSERT_TRUE(r.pose);
  EXPECT_EQ(r.pose->heading_deg, 0.0);
  EXPECT_EQ(r.pose->position.y, -170.0);
}

TEST(WireCigi, TimestampInTenMicroseconds) {
  PoseMessage m = sample_pose();
  m.has_sender_time = true;
  m.sender_time_s = 12.34567;
  const Bytes b = encode_cigi_host_datagram(1, 1, m, true);
  EXPECT_TRUE(b[4] & 0x04);
  const DecodeResult r = decode_cigi_host_datagram(b);
  ASSERT_TRUE(r.pose);
  EXPECT_TRUE(r.pose->has_sender_time);
  EXPECT_NEAR(r.pose->sender_time_s, 12.34567, 1e-9);
}

TEST(WireCigi, StartOfFrameLayoutAndRoundTrip) {
  const auto b = encode_cigi_start_of_frame(0xA1B2C3D4, 0x01020304, 0x00FFEE11, kCigiModeOperate, false, 9);
  EXPECT_EQ(b[0], 101);
  EXPECT_EQ(b[1], 24);
  EXPECT_EQ(b[2], 3);
  EXPECT_EQ(b[4], 9);
  EXPECT_EQ(b[5], 0x35);  // mode 1 | timestamp valid | minor version 3 << 4
  std::uint16_t magic;
  std::uint32_t ig_frame, ts, last;
  std::memcpy(&magic, &b[6], 2);
  std::memcpy(&ig_frame, &b[8], 4);
  std::memcpy(&ts, &b[12], 4);
  std::memcpy(&last, &b[16], 4);
  EXPECT_EQ(magic, 0x8000);
  EXPECT_EQ(ig_frame, 0xA1B2C3D4u);
  EXPECT_EQ(ts, 0x00FFEE11u);
  EXPECT_EQ(last, 0x01020304u);
  for (bool swap : {false, true}) {
    const auto s = encode_cigi_start_of_frame(77, 66, 55, kCigiModeStandby, swap);
    const StartOfFrameResult r = decode_cigi_start_of_frame(s);
    ASSERT_TRUE(r.sof);
    EXPECT_EQ(r.sof->ig_frame, 77u);
    EXPECT_EQ(r.sof->last_host_frame, 66u);
    EXPECT_EQ(r.sof->timestamp_10us, 55u);
    EXPECT_EQ(r.sof->ig_mode, 0u);
    EXPECT_EQ(r.sof->minor_version, 3);
    EXPECT_TRUE(r.sof->timestamp_valid);
    EXPECT_EQ(r.sof->byte_swapped, swap);
  }
  auto bad = b;
  bad[0] = 1;
  EXPECT_EQ(decode_cigi_start_of_frame(bad).reject, Reject::UnknownPacket);
  bad = b;
  bad[2] = 2;
  EXPECT_EQ(decode_cigi_start_of_frame(bad).reject, Reject::BadVersion);
  bad = b;
  bad[6] = 0x12;  // neither 0x80 0x00 nor 0x00 0x80
  bad[7] = 0x12;
  EXPECT_EQ(decode_cigi_start_of_frame(bad).reject, Reject::BadMagic);
  bad = b;
  bad[1] = 0;
  EXPECT_EQ(decode_cigi_start_of_frame(bad).reject, Reject::Truncated);
  EXPECT_EQ(decode_cigi_start_of_frame(std::span<const std::uint8_t>(b.data(), 20)).reject, Reject::TooShort);
}

TEST(WireCigi, EncoderToleratesGarbage) {
  PoseMessage m = sample_pose();
  m.roll_deg = 1e300;  // beyond float: written as Inf
  m.has_sender_time = true;
  m.sender_time_s = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(decode_cigi_host_datagram(encode_cigi_host_datagram(1, 1, m, false)).reject, Reject::NonFinite);
  m = sample_pose();
  m.has_sender_time = true;
  m.sender_time_s = -1e300;
  EXPECT_TRUE(decode_cigi_host_datagram(encode_cigi_host_datagram(1, 1, m, true)).pose);
}

TEST(WireCigiRandomized, MutatedDatagramsNeverYieldBadPoses) {
  std::mt19937_64 rng(4242);
  std::vector<Bytes> seeds;
  for (int i = 0; i < 32; ++i) {
    Bytes d = encode_cigi_host_datagram(static_cast<std::uint32_t>(rng()), rng() % 3, random_pose(rng, true),
                                        (i & 1) != 0);
    if (i % 4 == 2) {  // add an unknown packet and a second entity
      Bytes extra(16, 0);
      extra[0] = 0x55;
      extra[1] = 16;
      d.insert(d.begin() + 24, extra.begin(), extra.end());
      Bytes again(d.end() - 48, d.end());
      again[2] = 3;
      d.insert(d.end(), again.begin(), again.end());
    }
    seeds.push_back(std::move(d));
  }
  int accepted = 0, nopose = 0, truncated = 0;
  for (int i = 0; i < 200000; ++i) {
    const Bytes b = wire_test::mutate(rng, seeds[rng() % seeds.size()], 600);
    const DecodeResult r = decode_cigi_host_datagram(b);
    wire_test::check_result(r);
    if (HasFatalFailure()) return;
    if (r.reject == Reject::NoPose) {
      ASSERT_TRUE(r.host_frame.has_value());
      ASSERT_TRUE(r.ig_mode.has_value());
      ASSERT_LE(*r.ig_mode, 3u);
    }
    accepted += r.pose ? 1 : 0;
    nopose += (r.reject == Reject::NoPose) ? 1 : 0;
    truncated += (r.reject == Reject::Truncated) ? 1 : 0;
    const StartOfFrameResult s = decode_cigi_start_of_frame(b);
    ASSERT_NE(s.sof.has_value(), s.reject.has_value());
  }
  EXPECT_GT(accepted, 1000);
  EXPECT_GT(nopose, 100);
  EXPECT_GT(truncated, 1000);
}

}  // namespace
