// CanPoseSource without a kernel: frames handed in with their receive times,
// exactly as poll() does per frame read from the socket.
#include <gtest/gtest.h>

#include <vector>

#include "io/can/can_pose_source.h"
#include "io/wire/can_fd_pose.h"
#include "io/wire/canaerospace.h"

namespace {
using namespace ig::io;

wire::PoseMessage geodetic_pose(double heading) {
  wire::PoseMessage m;
  m.frame = wire::PoseMessage::Frame::Geodetic;
  m.position = {46.5, 7.9, 1200.0};
  m.heading_deg = heading;
  m.pitch_deg = 2.0;
  m.roll_deg = -3.0;
  return m;
}

struct Collector {
  std::vector<wire::PoseMessage> poses;
  std::vector<can::CanFormat> formats;
  can::CanPoseSource::PoseSink sink() {
    return [this](const wire::PoseMessage& m, double, can::CanFormat f) {
      poses.push_back(m);
      formats.push_back(f);
    };
  }
};

can::CanPoseSource make_source() {
  can::CanPoseSourceOptions o;
  o.ifname = "unused0";  // never opened: handle_frame only
  return can::CanPoseSource(o);
}

TEST(CanPoseSource, OnePosePerSenderCycle) {
  auto src = make_source();
  Collector c;
  wire::CanAerospaceEncoder enc;
  for (int i = 0; i < 5; ++i)
    for (const auto& f : enc.encode(geodetic_pose(10.0 * i))) src.handle_frame(f, 0.01 * i, c.sink());
  ASSERT_EQ(c.poses.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    EXPECT_DOUBLE_EQ(c.poses[i].heading_deg, 10.0 * i);
    EXPECT_EQ(c.formats[i], can::CanFormat::CanAerospace);
  }
  EXPECT_EQ(src.canaerospace_stats().code_gaps, 0u);
}

TEST(CanPoseSource, StaleFieldBlocksThePoseAndIsReported) {
  auto src = make_source();
  Collector c;
  wire::CanAerospaceEncoder enc;
  const auto frames = enc.encode(geodetic_pose(90.0));
  // Latitude (frames 4, 5) arrives 1 s before everything else: too old.
  src.handle_frame(frames[4], 0.0, c.sink());
  src.handle_frame(frames[5], 0.0, c.sink());
  for (size_t k = 0; k < frames.size(); ++k)
    if (k != 4 && k != 5) src.handle_frame(frames[k], 1.0, c.sink());
  EXPECT_TRUE(c.poses.empty());
  EXPECT_EQ(src.stale_cycles(), 1u);
  EXPECT_TRUE(src.last_stale().stale & wire::can_field::kLatitude);
  EXPECT_FALSE(src.summary()["assembler"]["stale_fields"].empty());
}

TEST(CanPoseSource, FdPoseAndItsRejects) {
  auto src = make_source();
  Collector c;
  wire::PoseMessage m = geodetic_pose(45.0);
  m.sequence = 7;
  m.has_sequence = true;
  auto f = wire::encode_can_fd_pose(m);
  src.handle_frame(f, 0.0, c.sink());
  ASSERT_EQ(c.poses.size(), 1u);
  EXPECT_EQ(c.formats[0], can::CanFormat::CanFd);
  EXPECT_EQ(c.poses[0].sequence, 7u);
  f.data[20] ^= 0x10;  // CRC no longer matches
  src.handle_frame(f, 0.1, c.sink());
  EXPECT_EQ(c.poses.size(), 1u);
  EXPECT_EQ(src.fd_stats().frames, 2u);
  EXPECT_EQ(src.fd_stats().rejects.size(), 1u);
}

TEST(CanPoseSource, UnopenableInterfaceIsReportedNotThrown) {
  can::CanPoseSourceOptions o;
  o.ifname = "igtest_none0";
  can::CanPoseSource src(o);
  Collector c;
  EXPECT_EQ(src.poll(c.sink()), 0);
  EXPECT_FALSE(src.socket().is_open());
  // No AF_CAN here ("socket(AF_CAN)"), or AF_CAN without that interface.
  EXPECT_NE(src.socket().last_error().find("igtest_none0"), std::string::npos) << src.socket().last_error();
  EXPECT_EQ(src.socket().stats().open_failures, 1u);
}

}  // namespace
