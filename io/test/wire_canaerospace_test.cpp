// Host-side CANaerospace codec: frame decode (malformed frames counted and
// ignored), the encoder and the pose assembler. No sockets.
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

}  // namespace
