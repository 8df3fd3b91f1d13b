// Datagrams to the pose filter (io/pose_intake.h) and recordings (io/recording.h).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "io/pose.h"
#include "io/pose_intake.h"
#include "io/recording.h"
#include "io/wire/cigi.h"
#include "io/wire/cigi_environment.h"
#include "io/wire/native.h"

namespace {

using ig::io::Protocol;

ig::io::wire::PoseMessage local_pose(std::uint32_t seq, double t) {
  ig::io::wire::PoseMessage m;
  m.position = {100.0 + seq, 200.0, 300.0};
  m.heading_deg = 45.0;
  m.sequence = seq;
  m.has_sequence = true;
  m.sender_time_s = t;
  m.has_sender_time = true;
  return m;
}

TEST(PoseIntake, ValidPacketReachesTheFilter) {
  ig::io::PoseFilter filter;
  ig::io::PoseIntake intake(filter, nullptr);
  const auto bytes = ig::io::wire::encode_native(local_pose(1, 10.0));
  intake.handle(Protocol::Native, bytes, 10.0);
  EXPECT_EQ(intake.counters(Protocol::Native).ok, 1u);
  EXPECT_EQ(intake.last_source(), "native");
  const auto p = filter.sample(10.2);
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(p->position.x, 101.0, 1e-9);
  EXPECT_NEAR(ig::io::hpr_from_attitude(p->attitude).heading_deg, 45.0, 1e-9);
}

TEST(PoseIntake, CorruptPacketIsCountedWithItsReasonAndDropped) {
  ig::io::PoseFilter filter;
  ig::io::PoseIntake intake(filter, nullptr);
  auto bytes = ig::io::wire::encode_native(local_pose(1, 10.0));
  bytes[40] ^= 0x5A;
  intake.handle(Protocol::Native, bytes, 10.0);
  const std::uint8_t garbage[7] = {1, 2, 3, 4, 5, 6, 7};
  intake.handle(Protocol::Cigi, garbage, 10.0);
  EXPECT_EQ(intake.counters(Protocol::Native).bad, 1u);
  EXPECT_EQ(intake.counters(Protocol::Native).reasons.size(), 1u);
  EXPECT_EQ(intake.counters(Protocol::Cigi).bad, 1u);
  EXPECT_EQ(intake.total_ok(), 0u);
  EXPECT_FALSE(filter.sample(10.1).has_value());
}

TEST(PoseIntake, GeodeticPoseNeedsAGeoreference) {
  ig::io::PoseFilter filter;
  ig::io::PoseIntake no_georef(filter, nullptr);
  auto m = local_pose(1, 10.0);
  m.frame = ig::io::wire::PoseMessage::Frame::Geodetic;
  m.position = {46.5, 7.9, 1000.0};
  const auto bytes = ig::io::wire::encode_native(m);
  no_georef.handle(Protocol::Native, bytes, 10.0);
  EXPECT_EQ(no_georef.counters(Protocol::Native).reasons.at("geodetic-without-georeference"), 1u);

  ig::io::PoseFilter filter2;
  ig::io::PoseIntake placed(filter2, [](double lat, double lon, double alt) {
    return std::optional<glm::dvec3>(glm::dvec3(lon * 1000.0, lat * 1000.0, alt));
  });
  placed.handle(Protocol::Native, bytes, 10.0);
  const auto p = filter2.sample(10.2);
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(p->position.x, 7900.0, 1e-6);
  EXPECT_NEAR(p->position.y, 46500.0, 1e-6);
}

TEST(Recording, RoundTripAndTruncatedTail) {
  const auto path = (std::filesystem::temp_directory_path() / "ig_recording_test.igrec").string();
  {
    ig::io::RecordingWriter w(path);
    const auto a = ig::io::wire::encode_native(local_pose(1, 1.0));
    const std::uint8_t b[3] = {9, 8, 7};
    w.write(Protocol::Native, a, 1.5);
    w.write(Protocol::FgNetFdm, b, 2.5);
    EXPECT_EQ(w.count(), 2u);
  }
  auto records = ig::io::read_recording(path);
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0].protocol, Protocol::Native);
  EXPECT_EQ(records[0].bytes.size(), ig::io::wire::kNativeSize);
  EXPECT_DOUBLE_EQ(records[1].receive_time_s, 2.5);
  EXPECT_EQ(records[1].bytes, (std::vector<std::uint8_t>{9, 8, 7}));
  // A record cut short (the IG killed mid-write) is ignored, the rest kept.
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 2);
  EXPECT_EQ(ig::io::read_recording(path).size(), 1u);
  std::filesystem::remove(path);
}

TEST(Recording, BadFilesAreNamed) {
  const auto path = (std::filesystem::temp_directory_path() / "ig_not_a_recording.bin").string();
  std::ofstream(path) << "hello world";
  try {
    ig::io::read_recording(path);
    FAIL() << "expected an error";
  } catch (const ig::io::RecordingError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
  }
  EXPECT_THROW(ig::io::read_recording("/nonexistent/x.igrec"), ig::io::RecordingError);
  std::filesystem::remove(path);
}

}  // namespace

// A CIGI Rate Control for the ownship rides on its poses: the filter
// dead-reckons with it between host frames, also for the host frames after
// it that carry no Rate Control; all-zero rates stop that.
TEST(PoseIntake, CigiRateControlDeadReckonsTheOwnship) {
  using namespace ig::io::wire;
  auto place = [](double lat, double lon, double alt) {
    return std::optional<glm::dvec3>(glm::dvec3(lon * 1e5, lat * 1e5, alt));
  };
  PoseMessage m;
  m.frame = PoseMessage::Frame::Geodetic;
  m.position = {0.01, 0.02, 500.0};
  m.heading_deg = 90.0;  // east
  auto sampled = [&](std::optional<CigiRateControl> rates) {
    ig::io::PoseFilter filter;
    ig::io::PoseIntake intake(filter, place);
    for (std::uint32_t frame : {1u, 2u}) {  // two host frames 1/60 s apart, the same position
      auto d = encode_cigi_host_datagram(frame, kCigiModeOperate, m, false);
      if (rates && frame == 1) {
        const auto rc = encode_cigi_rate_control(*rates, false);
        d.insert(d.end(), rc.begin(), rc.end());
      }
      intake.handle(Protocol::Cigi, d, 10.0 + frame / 60.0);
    }
    return *filter.sample(10.1);
  };
  const auto still = sampled(std::nullopt);
  const auto north = sampled(CigiRateControl{0, 0, false, false, {100, 0, 0}, {0, 0, 0}});  // world: x north
  const auto ahead = sampled(CigiRateControl{0, 0, false, true, {100, 0, 0}, {0, 0, 0}});   // body: x forward (east)
  const auto zero = sampled(CigiRateControl{0, 0, false, false, {0, 0, 0}, {0, 0, 0}});
  EXPECT_GT(north.position.y - still.position.y, 1.0);
  EXPECT_NEAR(north.position.x, still.position.x, 1e-6);
  EXPECT_GT(ahead.position.x - still.position.x, 1.0);
  EXPECT_NEAR(ahead.position.y, still.position.y, 1e-6);
  EXPECT_EQ(zero.position, still.position);
}
