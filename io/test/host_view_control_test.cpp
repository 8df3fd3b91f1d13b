// CIGI View Control / View Definition: decoded in both byte orders and
// applied to a channel, which then equals the channel a config file sets up.

#include <gtest/gtest.h>

#include <bit>
#include <vector>

#include "io/host_view_control.h"
#include "io/scenario.h"
#include "io/wire/cigi.h"
#include "io/wire/cigi_views.h"

namespace {

using namespace ig::io;
using namespace ig::io::wire;

template <typename... Packets>
std::vector<std::uint8_t> datagram(bool swap, const Packets&... packets) {
  std::vector<std::uint8_t> d = encode_cigi_host_datagram(1, kCigiModeOperate, {}, swap);
  (d.insert(d.end(), packets.begin(), packets.end()), ...);
  return d;
}

// The channel a config gives: 30 deg right, 5 deg down, 40 deg vertical FOV.
ChannelSpec from_config() {
  const Scenario s = parse_scenario(R"({
    "name": "views", "terrain": {"generator": {"size": 65, "seed": 1}},
    "path": {"keys": [{"t": 0, "position": [0, 0, 100], "hpr": [0, 0, 0]}]},
    "channels": [{"name": "right", "heading_offset_deg": 30, "pitch_offset_deg": -5, "roll_offset_deg": 0,
                  "fov_y_deg": 40}]})");
  return s.channels.at(0);
}

TEST(HostViewControl, HostSetUpChannelEqualsTheConfigs) {
  const ChannelSpec want = from_config();
  for (bool swap : {false, true}) {
    ChannelSpec got;
    got.name = want.name;
    CigiViewControl c;
    c.yaw_deg = 30.0f;
    c.pitch_deg = -5.0f;
    c.roll_deg = 0.0f;
    CigiViewDefinition d;
    d.top_deg = 20.0f;
    d.bottom_deg = -20.0f;
    HostViewControl views;
    views.take(datagram(swap, encode_cigi_view_control(c, swap), encode_cigi_view_definition(d, swap)),
               [&](std::uint16_t v) { return v == 0 ? &got : nullptr; });
    EXPECT_EQ(views.applied(), 2u);
    EXPECT_TRUE(views.notes().empty());
    EXPECT_EQ(got.heading_offset_deg, want.heading_offset_deg);
    EXPECT_EQ(got.pitch_offset_deg, want.pitch_offset_deg);
    EXPECT_EQ(got.roll_offset_deg, want.roll_offset_deg);
    ASSERT_TRUE(got.fov_y_deg && want.fov_y_deg);
    EXPECT_EQ(*got.fov_y_deg, *want.fov_y_deg);
  }
}

TEST(HostViewControl, OnlyEnabledFieldsChangeAndTheRestIsCounted) {
  ChannelSpec ch;
  ch.heading_offset_deg = 10;
  ch.pitch_offset_deg = 2;
  HostViewControl views;
  auto lookup = [&](std::uint16_t v) { return v == 0 ? &ch : nullptr; };
  CigiViewControl c;
  c.pitch_deg = -3.0f;  // heading and roll not enabled: kept
  c.x_m = 1.5f;         // eye offset: only x given, y and z kept
  views.take(datagram(false, encode_cigi_view_control(c, false)), lookup);
  EXPECT_EQ(ch.heading_offset_deg, 10);
  EXPECT_EQ(ch.pitch_offset_deg, -3);
  EXPECT_EQ(ch.eye_offset_m, (std::array<double, 3>{1.5, 0.0, 0.0}));
  EXPECT_EQ(views.notes().count("view-position-offset-ignored"), 0u);
  CigiViewDefinition asym;
  asym.top_deg = 30.0f;
  asym.bottom_deg = -10.0f;
  views.take(datagram(true, encode_cigi_view_definition(asym, true)), lookup);
  EXPECT_EQ(*ch.fov_y_deg, 40.0);
  EXPECT_EQ(views.notes().at("asymmetric-frustum"), 1u);
  CigiViewControl other = c;
  other.view = 3;  // no such channel
  CigiViewControl entity = c;
  entity.entity = 9;  // not the ownship: the view rides on entity 9
  entity.pitch_deg = 50.0f;
  CigiViewDefinition bad;
  bad.top_deg = -5.0f;
  bad.bottom_deg = 5.0f;  // top below bottom
  views.take(datagram(false, encode_cigi_view_control(other, false), encode_cigi_view_control(entity, false),
                      encode_cigi_view_definition(bad, false)),
             lookup);
  EXPECT_EQ(ch.pitch_offset_deg, 50);
  EXPECT_EQ(*ch.fov_y_deg, 40.0);
  EXPECT_EQ(views.notes().at("view-unknown-channel"), 1u);
  EXPECT_EQ(views.notes().count("view-entity-not-ownship"), 0u);  // views ride on any entity now
  EXPECT_EQ(ch.entity, 9);
  EXPECT_EQ(views.notes().at("view-out-of-range"), 1u);
  // A packet with the wrong size is dropped and counted.
  auto wrong = encode_cigi_view_control(c, false);
  std::vector<std::uint8_t> d = datagram(false, wrong);
  d[d.size() - kCigiViewControlSize + 1] = 24;  // after the IG Control and the ownship
  d.resize(d.size() - 8);
  views.take(d, lookup);
  EXPECT_EQ(views.notes().at("view-wrong-size"), 1u);
}

TEST(HostViewControl, HandWrittenBigEndianViewDefinition) {
  std::vector<std::uint8_t> d = encode_cigi_host_datagram(1, kCigiModeOperate, {}, std::endian::native != std::endian::big);
  std::vector<std::uint8_t> p(32, 0);
  p[0] = 21;
  p[1] = 32;
  p[3] = 0;        // view 0
  p[5] = 0x30;     // top and bottom enabled
  p[24] = 0x41;    // top 12.5 = 0x41480000
  p[25] = 0x48;
  p[28] = 0xC1;    // bottom -12.5
  p[29] = 0x48;
  d.insert(d.end(), p.begin(), p.end());
  const CigiViewPackets v = decode_cigi_view_packets(d);
  ASSERT_EQ(v.definitions.size(), 1u);
  EXPECT_EQ(*v.definitions[0].top_deg, 12.5f);
  EXPECT_EQ(*v.definitions[0].bottom_deg, -12.5f);
  EXPECT_FALSE(v.definitions[0].near_m);
}

}  // namespace
