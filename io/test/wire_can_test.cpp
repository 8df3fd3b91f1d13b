// Host-side CAN codecs: CANaerospace frames, the pose assembler and the CAN FD
// single-frame pose. No sockets.
// Long because it covers three codecs (CANaerospace frames, the pose
// assembler, CAN FD) with their malformed-frame cases side by side.
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
#include "io/test/wire_test_support.h"

namespace {

using namespace ig::io::wire;
using wire_test::angle_diff;
using wire_test::random_pose;

PoseMessage sample_pose() {
  PoseMessage m;
  m.frame = PoseMessage::Frame::Geodetic;
  m.position = {37.6189123456789, -122.375987654321, 120.5};
  m.heading_deg = 280.0;
  m.pitch_deg = 3.5;
  m.roll_deg = -10.0;
  m.has_rates = true;
  m.body_rates_dps = {1.0, -0.5, 2.0};
  return m;
}

// Decodes `frames` and feeds every accepted value at time t.
void feed_all(const std::vector<CanFrame>& frames, CanAerospaceStats& st, CanPoseAssembler& as, double t,
              const CanAerospaceOptions& opt = {}) {
  for (const auto& f : frames) {
    if (auto v = decode_canaerospace(f, st, opt)) as.feed(*v, t);
  }
}

// ---------------------------------------------------------------------------
// CanFrame helpers

TEST(CanFrame, DlcLengthMapping) {
  EXPECT_EQ(can_dlc_to_len(8, false), 8u);
  EXPECT_EQ(can_dlc_to_len(15, false), 8u);
  EXPECT_EQ(can_dlc_to_len(9, true), 12u);
  EXPECT_EQ(can_dlc_to_len(15, true), 64u);
  EXPECT_EQ(can_len_to_dlc(64, true), 15);
  EXPECT_EQ(can_len_to_dlc(13, true), 10);
  EXPECT_EQ(can_len_to_dlc(20, false), 8);
  EXPECT_TRUE(can_len_valid(64, true));
  EXPECT_FALSE(can_len_valid(63, true));
  EXPECT_FALSE(can_len_valid(12, false));
  for (std::uint8_t d = 0; d < 16; ++d) EXPECT_EQ(can_len_to_dlc(can_dlc_to_len(d, true), true), d);
}

// ---------------------------------------------------------------------------
// CANaerospace frame decode

TEST(CanAerospace, FloatFrameLayoutAndRoundTrip) {
  const CanFrame f = make_canaerospace_float(canas_id::kHeading, 7, 200, 123.25f);
  EXPECT_EQ(f.id, 321u);
  EXPECT_EQ(f.len, 8);
  EXPECT_EQ(f.flags, 0);
  EXPECT_EQ(f.data[0], 7);
  EXPECT_EQ(f.data[1], kCanAsFloat);
  EXPECT_EQ(f.data[2], 0);
  EXPECT_EQ(f.data[3], 200);
  // 123.25f = 0x42F68000, big-endian in bytes 4..7.
  EXPECT_EQ(f.data[4], 0x42);
  EXPECT_EQ(f.data[5], 0xF6);
  EXPECT_EQ(f.data[6], 0x80);
  EXPECT_EQ(f.data[7], 0x00);
  CanAerospaceStats st;
  auto v = decode_canaerospace(f, st);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->id, 321);
  EXPECT_EQ(v->node_id, 7);
  EXPECT_EQ(v->data_type, kCanAsFloat);
  EXPECT_EQ(v->message_code, 200);
  EXPECT_EQ(v->value, 123.25f);
  EXPECT_EQ(st.frames, 1u);
  EXPECT_EQ(st.accepted, 1u);
  EXPECT_EQ(st.rejected(), 0u);
}

TEST(CanAerospace, DoubleHalvesAccepted) {
  const double lat = 47.123456789012;
  const auto bits = std::bit_cast<std::uint64_t>(lat);
  CanAerospaceStats st;
  auto h = decode_canaerospace(
      make_canaerospace_frame(canas_id::kLatitude, 1, kCanAsDoubleH, 0, 5, static_cast<std::uint32_t>(bits >> 32)), st);
  auto l = decode_canaerospace(
      make_canaerospace_frame(canas_id::kLatitude, 1, kCanAsDoubleL, 0, 5, static_cast<std::uint32_t>(bits)), st);
  ASSERT_TRUE(h && l);
  EXPECT_EQ(h->raw, static_cast<std::uint32_t>(bits >> 32));
  EXPECT_EQ(l->raw, static_cast<std::uint32_t>(bits));
  EXPECT_EQ(st.code_gaps, 0u);  // DOUBLEL has its own continuity slot
}

TEST(CanAerospace, MalformedFramesCountedAndIgnored) {
  CanAerospaceStats st;
  const CanFrame good = make_canaerospace_float(canas_id::kBodyPitch, 1, 0, 2.0f);

  CanFrame f = good;
  f.len = 7;
  EXPECT_FALSE(decode_canaerospace(f, st));
  EXPECT_EQ(st.wrong_dlc, 1u);
  EXPECT_EQ(st.last_reject, CanAsReject::WrongDlc);
  f.len = 0;
  EXPECT_FALSE(decode_canaerospace(f, st));
  EXPECT_EQ(st.wrong_dlc, 2u);

  f = good;
  f.id = 0x123;
  EXPECT_FALSE(decode_canaerospace(f, st));
  EXPECT_EQ(st.unknown_id, 1u);
  EXPECT_EQ(st.last_reject, CanAsReject::UnknownId);
  f.id = 1038;  // GPS height: a CANaerospace id the IG does not use
  EXPECT_FALSE(decode_canaerospace(f, st));
  EXPECT_EQ(st.unknown_id, 2u);

  f = good;
  f.data[1] = kCanAsDoubleH;  // pitch must be FLOAT
  EXPECT_FALSE(decode_canaerospace(f, st));
  EXPECT_EQ(st.wrong_type, 1u);
  EXPECT_EQ(st.last_reject, CanAsReject::WrongDataType);
  f = make_canaerospace_frame(canas_id::kLatitude, 1, 6 /*LONG*/, 0, 0, 0);
  EXPECT_FALSE(decode_canaerospace(f, st));
  EXPECT_EQ(st.wrong_type, 2u);

  f = make_canaerospace_float(canas_id::kBodyRoll, 1, 0, std::numeric_limits<float>::quiet_NaN());
  EXPECT_FALSE(decode_canaerospace(f, st));
  EXPECT_EQ(st.non_finite, 1u);
  EXPECT_EQ(st.last_reject, CanAsReject::NonFinite);
  f = make_canaerospace_float(canas_id::kBodyRoll, 1, 0, -std::numeric_limits<float>::infinity());
  EXPECT_FALSE(decode_canaerospace(f, st));
  EXPECT_EQ(st.non_finite, 2u);

  for (std::uint8_t flag : {kCanFlagFd, kCanFlagExtended, kCanFlagRtr, kCanFlagError}) {
    f = good;
    f.flags = flag;
    EXPECT_FALSE(decode_canaerospace(f, st));
  }
  EXPECT_EQ(st.not_classic, 4u);
  EXPECT_EQ(st.last_reject, CanAsReject::NotClassicFrame);

  CanAerospaceOptions only5;
  only5.node_id = 5;
  EXPECT_FALSE(decode_canaerospace(good, st, only5));
  EXPECT_EQ(st.wrong_node, 1u);
  EXPECT_EQ(st.last_reject, CanAsReject::WrongNode);
  f = good;
  f.data[0] = 5;
  EXPECT_TRUE(decode_canaerospace(f, st, only5));

  EXPECT_EQ(st.accepted, 1u);
  EXPECT_EQ(st.frames, st.accepted + st.rejected());
}

TEST(CanAerospace, MessageCodeContinuity) {
  CanAerospaceStats st;
  auto send = [&](std::uint16_t id, std::uint8_t code) {
    ASSERT_TRUE(decode_canaerospace(make_canaerospace_float(id, 1, code, 1.0f), st));
  };
  send(311, 0);
  send(311, 1);
  send(311, 2);
  EXPECT_EQ(st.code_gaps, 0u);
  send(311, 4);  // 3 lost
  EXPECT_EQ(st.code_gaps, 1u);
  send(311, 4);  // repeated
  EXPECT_EQ(st.code_gaps, 2u);
  send(312, 77);  // first on another id: no gap
  send(312, 78);
  EXPECT_EQ(st.code_gaps, 2u);
  send(321, 254);
  send(321, 255);
  send(321, 0);  // wrap
  send(321, 1);
  EXPECT_EQ(st.code_gaps, 2u);
  // Rejected frames do not disturb the tracking.
  CanFrame bad = make_canaerospace_float(321, 1, 9, 1.0f);
  bad.len = 4;
  EXPECT_FALSE(decode_canaerospace(bad, st));
  send(321, 2);
  EXPECT_EQ(st.code_gaps, 2u);
}

// ---------------------------------------------------------------------------
// Encoder + assembler

TEST(CanPoseAssembler, EncodeDecodeRoundTripDoublePosition) {
  CanAerospaceEncoder enc;
  const PoseMessage in = sample_pose();
  const auto frames = enc.encode(in);
  ASSERT_EQ(frames.size(), 11u);  // 4 floats, 2 pairs, 3 rates
  CanAerospaceStats st;
  CanPoseAssembler as;
  feed_all(frames, st, as, 10.0);
  EXPECT_EQ(st.accepted, 11u);
  StaleFields sf;
  auto out = as.pose(10.01, sf);
  ASSERT_TRUE(out) << sf.missing << " " << sf.stale;
  EXPECT_FALSE(sf.any());
  EXPECT_EQ(out->frame, PoseMessage::Frame::Geodetic);
  EXPECT_EQ(out->position.x, in.position.x);  // f64 pairs are exact
  EXPECT_EQ(out->position.y, in.position.y);
  EXPECT_NEAR(out->position.z, in.position.z, 1e-4);
  EXPECT_NEAR(out->heading_deg, in.heading_deg, 1e-4);
  EXPECT_NEAR(out->pitch_deg, in.pitch_deg, 1e-5);
  EXPECT_NEAR(out->roll_deg, in.roll_deg, 1e-5);
  ASSERT_TRUE(out->has_rates);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(out->body_rates_dps[i], in.body_rates_dps[i], 1e-6);
  EXPECT_TRUE(is_valid_output(*out));

  // Next pose from the same encoder: continuous message codes.
  feed_all(enc.encode(in), st, as, 10.02);
  EXPECT_EQ(st.code_gaps, 0u);
  EXPECT_EQ(as.stats().orphan_low + as.stats().half_mismatch + as.stats().orphan_high, 0u);
}

TEST(CanPoseAssembler, RandomRoundTrips) {
  std::mt19937_64 rng(5);
  for (int k = 0; k < 2000; ++k) {
    PoseMessage in = random_pose(rng, true);
    CanAerospaceEncodeConfig cfg;
    cfg.position_as_double = (k & 1) == 0;
    cfg.altitude_id = k % 3 == 0 ? 320 : (k % 3 == 1 ? 322 : 332);
    CanAerospaceEncoder enc(cfg);
    CanPoseConfig pc;
    pc.altitude_id = cfg.altitude_id;
    CanPoseAssembler as(pc);
    CanAerospaceStats st;
    feed_all(enc.encode(in), st, as, 1.0);
    StaleFields sf;
    auto out = as.pose(1.0, sf);
    ASSERT_TRUE(out);
    EXPECT_TRUE(is_valid_output(*out));
    const double pos_tol = cfg.position_as_double ? 0.0 : 2e-5 * 180.0;
    EXPECT_NEAR(out->position.x, in.position.x, pos_tol);
    EXPECT_NEAR(std::fabs(angle_diff(out->position.y, in.position.y)), 0.0, pos_tol);
    EXPECT_NEAR(out->position.z, in.position.z, 2e-3);
    EXPECT_NEAR(angle_diff(out->heading_deg, in.heading_deg), 0.0, 1e-4);
    EXPECT_NEAR(out->pitch_deg, in.pitch_deg, 1e-4);
    EXPECT_NEAR(angle_diff(out->roll_deg, in.roll_deg), 0.0, 1e-4);
    EXPECT_EQ(out->has_rates, in.has_rates);
    if (in.has_rates) {
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(out->body_rates_dps[i], in.body_rates_dps[i], 1e-4);
    }
  }
}

TEST(CanPoseAssembler, DoubleLowWithoutHighIsNotUsed) {
  const double lat = 10.5;
  const auto bits = std::bit_cast<std::uint64_t>(lat);
  const auto hi = static_cast<std::uint32_t>(bits >> 32);
  const auto lo = static_cast<std::uint32_t>(bits);
  CanAerospaceStats st;
  CanPoseAssembler as;
  auto feed = [&](std::uint8_t type, std::uint8_t code, std::uint32_t raw) {
    auto v = decode_canaerospace(make_canaerospace_frame(canas_id::kLatitude, 1, type, 0, code, raw), st);
    ASSERT_TRUE(v);
    as.feed(*v, 0.0);
  };
  feed(kCanAsDoubleL, 0, lo);  // no high half
  EXPECT_EQ(as.stats().orphan_low, 1u);
  EXPECT_EQ(as.stats().used, 0u);
  feed(kCanAsDoubleH, 1, hi);
  feed(kCanAsDoubleL, 2, lo);  // code mismatch
  EXPECT_EQ(as.stats().half_mismatch, 1u);
  EXPECT_EQ(as.stats().used, 0u);
  feed(kCanAsDoubleH, 3, hi);
  feed(kCanAsDoubleH, 4, hi);  // first high never completed
  EXPECT_EQ(as.stats().orphan_high, 1u);
  feed(kCanAsDoubleL, 4, lo);
  EXPECT_EQ(as.stats().used, 1u);
  StaleFields sf;
  EXPECT_FALSE(as.pose(0.0, sf));
  EXPECT_EQ(sf.missing & can_field::kLatitude, 0u);
  EXPECT_NE(sf.missing & can_field::kLongitude, 0u);

  // A pair that assembles to NaN or an out-of-range latitude is not used.
  const auto nan_bits = std::bit_cast<std::uint64_t>(std::numeric_limits<double>::quiet_NaN());
  feed(kCanAsDoubleH, 5, static_cast<std::uint32_t>(nan_bits >> 32));
  feed(kCanAsDoubleL, 5, static_cast<std::uint32_t>(nan_bits));
  EXPECT_EQ(as.stats().non_finite, 1u);
  const auto big = std::bit_cast<std::uint64_t>(95.0);
  feed(kCanAsDoubleH, 6, static_cast<std::uint32_t>(big >> 32));
  feed(kCanAsDoubleL, 6, static_cast<std::uint32_t>(big));
  EXPECT_EQ(as.stats().out_of_range, 1u);
  EXPECT_EQ(as.stats().used, 1u);
}

TEST(CanPoseAssembler, StaleFieldsReportedNotReused) {
  CanPoseConfig pc;
  pc.max_age_s = 0.1;
  CanPoseAssembler as(pc);
  CanAerospaceEncoder enc;
  CanAerospaceStats st;
  StaleFields sf;

  EXPECT_FALSE(as.pose(0.0, sf));  // nothing yet
  EXPECT_EQ(sf.missing, (1u << can_field::kCount) - 1u);
  EXPECT_EQ(sf.stale, 0u);

  feed_all(enc.encode(sample_pose()), st, as, 1.0);
  ASSERT_TRUE(as.pose(1.05, sf));
  EXPECT_FALSE(sf.any());

  ASSERT_FALSE(as.pose(1.2, sf));
  EXPECT_EQ(sf.stale, (1u << can_field::kCount) - 1u);
  EXPECT_EQ(sf.missing, 0u);

  // Refresh attitude and altitude only: lat / lon stay stale -> no pose.
  feed_all({make_canaerospace_float(311, 1, 1, 1.0f), make_canaerospace_float(312, 1, 1, 2.0f),
            make_canaerospace_float(321, 1, 1, 3.0f), make_canaerospace_float(322, 1, 1, 4.0f)},
           st, as, 1.2);
  EXPECT_FALSE(as.pose(1.25, sf));
  EXPECT_EQ(sf.stale & (can_field::kLatitude | can_field::kLongitude),
            can_field::kLatitude | can_field::kLongitude);
  EXPECT_EQ(sf.stale & (can_field::kPitch | can_field::kRoll | can_field::kHeading | can_field::kAltitude), 0u);

  // Full refresh without rates: a pose, rates reported stale and not used.
  PoseMessage no_rates = sample_pose();
  no_rates.has_rates = false;
  feed_all(enc.encode(no_rates), st, as, 1.3);
  auto out = as.pose(1.3, sf);
  ASSERT_TRUE(out);
  EXPECT_FALSE(out->has_rates);
  EXPECT_EQ(sf.stale, can_field::kRollRate | can_field::kPitchRate | can_field::kYawRate);
  EXPECT_EQ(out->position.x, sample_pose().position.x);
  EXPECT_EQ(out->pitch_deg, 3.5);

  // Clock going backwards counts as fresh (age < 0).
  EXPECT_TRUE(as.pose(1.0, sf));
  EXPECT_GT(as.stats().poses, 0u);
  EXPECT_GT(as.stats().no_pose, 0u);
}

TEST(CanPoseAssembler, AltitudeSourceAndLocalMode) {
  CanPoseConfig pc;
  pc.altitude_id = 332;
  pc.require_position = false;
  CanPoseAssembler as(pc);
  CanAerospaceStats st;
  feed_all({make_canaerospace_float(311, 1, 0, 1.0f), make_canaerospace_float(312, 1, 0, 2.0f),
            make_canaerospace_float(321, 1, 0, 90.0f), make_canaerospace_float(322, 1, 0, 500.0f)},
           st, as, 0.0);
  EXPECT_EQ(as.stats().unused_id, 1u);  // 322 is not the configured source
  StaleFields sf;
  EXPECT_FALSE(as.pose(0.0, sf));
  EXPECT_EQ(sf.missing & can_field::kAltitude, can_field::kAltitude);
  feed_all({make_canaerospace_float(332, 1, 0, 1500.0f)}, st, as, 0.0);
  auto out = as.pose(0.0, sf);
  ASSERT_TRUE(out);
  EXPECT_EQ(out->frame, PoseMessage::Frame::Local);  // lat / lon never seen
  EXPECT_EQ(out->position, glm::dvec3(0.0, 0.0, 1500.0));
  // Once latitude is seen, position is required.
  feed_all({make_canaerospace_float(1036, 1, 0, 45.0f)}, st, as, 0.0);
  EXPECT_FALSE(as.pose(0.0, sf));
  EXPECT_EQ(sf.missing, can_field::kLongitude | can_field::kRollRate | can_field::kPitchRate | can_field::kYawRate);
  feed_all({make_canaerospace_float(1037, 1, 0, 7.0f)}, st, as, 0.0);
  out = as.pose(0.0, sf);
  ASSERT_TRUE(out);
  EXPECT_EQ(out->frame, PoseMessage::Frame::Geodetic);
  EXPECT_EQ(out->position, glm::dvec3(45.0, 7.0, 1500.0));
}

TEST(CanPoseAssembler, OutOfRangeValuesRejectedByValidation) {
  CanPoseAssembler as;
  CanAerospaceStats st;
  CanAerospaceEncoder enc;
  PoseMessage m = sample_pose();
  m.position.z = 5e6;  // beyond kMaxAbsAltitude
  feed_all(enc.encode(m), st, as, 0.0);
  StaleFields sf;
  EXPECT_FALSE(as.pose(0.0, sf));
  EXPECT_EQ(sf.reject, Reject::OutOfRange);
  // FLOAT longitude out of range is dropped at feed.
  feed_all({make_canaerospace_float(1037, 1, 9, 400.0f)}, st, as, 0.0);
  EXPECT_EQ(as.stats().out_of_range, 1u);
}

// ---------------------------------------------------------------------------
// CAN FD pose

void recrc(CanFrame& f) {
  const std::uint32_t c = crc32(std::span<const std::uint8_t>(f.data.data(), can_fd_offset::kCrc));
  bytes::store_u32(f.data.data() + can_fd_offset::kCrc, c, bytes::Order::Little);
}

PoseMessage full_pose() {
  PoseMessage m = sample_pose();
  m.has_velocity = true;
  m.velocity_mps = {-60.0, 10.0, 1.5};
  m.has_sequence = true;
  m.sequence = 42;
  m.has_sender_time = true;
  m.sender_time_s = 1234.5;
  return m;
}

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
