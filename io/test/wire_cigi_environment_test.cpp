// CIGI 3.3 environment and entity packets: hand-written bytes (big-endian,
// offsets from the ICD) against the decoder, round trips in both orders,
// every reject reason, unsupported opcodes, and the IG's answers.

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <cstring>
#include <vector>

#include "io/wire/cigi.h"
#include "io/wire/cigi_environment.h"
#include "io/wire/cigi_views.h"

namespace {

using namespace ig::io::wire;
using Bytes = std::vector<std::uint8_t>;

// A big-endian IG Control (host frame 7) and a packet of `size` bytes after it.
Bytes datagram_with(std::uint8_t op, std::size_t size) {
  Bytes b(24, 0);
  b[0] = 1;
  b[1] = 24;
  b[2] = 3;
  b[4] = 0x31;
  b[6] = 0x80;
  b[11] = 7;
  b.push_back(op);
  b.push_back(std::uint8_t(size));
  b.resize(24 + size, 0);
  return b;
}
void put_be(Bytes& b, std::size_t at, std::uint64_t v, int n) {
  for (int k = 0; k < n; ++k) b[at + std::size_t(n - 1 - k)] = std::uint8_t(v >> (8 * k));
}
void put_f32(Bytes& b, std::size_t at, float f) {
  std::uint32_t u;
  std::memcpy(&u, &f, 4);
  put_be(b, at, u, 4);
}
void put_f64(Bytes& b, std::size_t at, double d) {
  std::uint64_t u;
  std::memcpy(&u, &d, 8);
  put_be(b, at, u, 8);
}
// The packet behind an IG Control in the order its encoder wrote (`swap`:
// opposite to this machine's).
Bytes with_ig_control(std::span<const std::uint8_t> packet, bool swap) {
  Bytes d = datagram_with(0, 0);
  d.resize(24);
  const bool big = swap == (std::endian::native == std::endian::little);
  if (!big) {
    std::swap(d[6], d[7]);
    std::swap(d[8], d[11]);
  }
  d.insert(d.end(), packet.begin(), packet.end());
  return d;
}

TEST(CigiEnvironment, HandWrittenCelestialAndAtmosphereDecode) {
  Bytes d = datagram_with(kCigiOpCelestialSphereControl, 16);
  d[24 + 2] = 18;
  d[24 + 3] = 30;
  d[24 + 4] = 0x12;  // sun, date valid
  put_be(d, 24 + 8, 6212026, 4);
  Bytes a = datagram_with(kCigiOpAtmosphereControl, 32);
  a[24 + 2] = 1;
  put_f32(a, 24 + 8, 5000.0f);
  d.insert(d.end(), a.begin() + 24, a.end());
  const CigiHostPackets p = decode_cigi_host_packets(d);
  ASSERT_EQ(p.celestial.size(), 1u);
  EXPECT_EQ(p.celestial[0].hour, 18);
  EXPECT_EQ(p.celestial[0].minute, 30);
  EXPECT_TRUE(p.celestial[0].sun && p.celestial[0].date_valid && !p.celestial[0].ephemeris);
  EXPECT_EQ(p.celestial[0].month, 6);
  EXPECT_EQ(p.celestial[0].day, 21);
  EXPECT_EQ(p.celestial[0].year, 2026);
  ASSERT_EQ(p.atmosphere.size(), 1u);
  EXPECT_EQ(p.atmosphere[0].visibility_m, 5000.0f);
  EXPECT_TRUE(p.rejects.empty() && p.unsupported.empty());
}

TEST(CigiEnvironment, HandWrittenPositionRequestAndSegmentDecode) {
  Bytes d = datagram_with(kCigiOpPositionRequest, 8);
  put_be(d, 24 + 2, 3, 2);
  d[24 + 5] = 0x01 | (2 << 1);  // continuous, view
  Bytes s = datagram_with(kCigiOpCollisionSegmentDefinition, 40);
  s[24 + 4] = 9;
  s[24 + 5] = 1;
  put_f32(s, 24 + 28, 120.0f);  // z2: 120 m below the entity
  d.insert(d.end(), s.begin() + 24, s.end());
  const CigiHostPackets p = decode_cigi_host_packets(d);
  ASSERT_EQ(p.positions.size(), 1u);
  EXPECT_EQ(p.positions[0].of.object, 3);
  EXPECT_TRUE(p.positions[0].continuous);
  EXPECT_EQ(p.positions[0].of.object_class, kCigiObjectView);
  ASSERT_EQ(p.segments.size(), 1u);
  EXPECT_EQ(p.segments[0].segment, 9);
  EXPECT_TRUE(p.segments[0].enabled);
  EXPECT_EQ(p.segments[0].end, glm::dvec3(0, 0, 120));
}

TEST(CigiEnvironment, EveryPacketRoundTripsInBothOrders) {
  for (bool swap : {false, true}) {
    const CigiRateControl rc{0, 0, false, true, {50, 1, -2}, {3, 0.5, -10}};
    const CigiCelestialSphere cs{6, 5, true, true, false, false, true, 12, 31, 2099, 40.0f};
    const CigiAtmosphere at{true, 80, -5.0f, 1234.5f, 7.0f, 0.5f, 90.0f, 990.0f};
    const CigiWeatherControl wc{4,      2,      70,      3,     0,     2,     true,  true,  10.0f,
                                800.0f, 20.0f,  50.0f,  1500.0f, 300.0f, 75.0f, 12.0f, -1.0f, 270.0f};
    const CigiCollisionSegment sg{0, 4, true, {1, 2, 3}, {4, 5, 600}, 0xF0};
    const CigiPositionRequest pr{{0, 0, kCigiObjectEntity, 0}, true};
    const CigiEnvironmentRequest er{kCigiConditionsWeather, 9, {36.5, -118.25, 3000.0}};
    EXPECT_EQ(decode_cigi_host_packets(with_ig_control(encode_cigi_rate_control(rc, swap), swap)).rates.at(0), rc);
    EXPECT_EQ(decode_cigi_host_packets(with_ig_control(encode_cigi_celestial(cs, swap), swap)).celestial.at(0), cs);
    EXPECT_EQ(decode_cigi_host_packets(with_ig_control(encode_cigi_atmosphere(at, swap), swap)).atmosphere.at(0), at);
    EXPECT_EQ(decode_cigi_host_packets(with_ig_control(encode_cigi_weather(wc, swap), swap)).weather.at(0), wc);
    EXPECT_EQ(decode_cigi_host_packets(with_ig_control(encode_cigi_collision_segment(sg, swap), swap)).segments.at(0),
              sg);
    EXPECT_EQ(decode_cigi_host_packets(with_ig_control(encode_cigi_position_request(pr, swap), swap)).positions.at(0),
              pr);
    EXPECT_EQ(
        decode_cigi_host_packets(with_ig_control(encode_cigi_environment_request(er, swap), swap)).conditions.at(0),
        er);
  }
}

TEST(CigiEnvironment, MalformedPacketsAreRejectedWithTheirReason) {
  Bytes late = datagram_with(kCigiOpCelestialSphereControl, 16);
  late[24 + 2] = 24;  // hour 24
  Bytes bad_date = datagram_with(kCigiOpCelestialSphereControl, 16);
  bad_date[24 + 4] = 0x10;
  put_be(bad_date, 24 + 8, 2302026, 4);  // 30 February
  Bytes nan = datagram_with(kCigiOpAtmosphereControl, 32);
  put_f32(nan, 24 + 8, std::numeric_limits<float>::quiet_NaN());
  Bytes fog = datagram_with(kCigiOpAtmosphereControl, 32);
  put_f32(fog, 24 + 8, -1.0f);
  Bytes small = datagram_with(kCigiOpPositionRequest, 16);
  Bytes far = datagram_with(kCigiOpEnvironmentalConditionsRequest, 32);
  put_f64(far, 24 + 8, 91.0);
  Bytes cut = datagram_with(kCigiOpRateControl, 32);
  cut.resize(cut.size() - 4);
  const std::pair<Bytes, QueryReject> cases[] = {
      {late, QueryReject::OutOfRange},  {bad_date, QueryReject::OutOfRange}, {nan, QueryReject::NonFinite},
      {fog, QueryReject::OutOfRange},   {small, QueryReject::WrongSize},     {far, QueryReject::OutOfRange},
      {cut, QueryReject::Truncated}};
  for (const auto& [bytes, reason] : cases) {
    const CigiHostPackets p = decode_cigi_host_packets(bytes);
    ASSERT_EQ(p.rejects.size(), 1u) << query_reject_name(reason);
    EXPECT_EQ(p.rejects[0], reason);
    EXPECT_TRUE(p.celestial.empty() && p.atmosphere.empty() && p.positions.empty() && p.rates.empty());
  }
}

TEST(CigiEnvironment, UnsupportedOpcodesAndDatabaseRequestsAreReported) {
  Bytes d = datagram_with(4, 32);  // Component Control
  d.push_back(35);                 // Short Symbol Control
  d.push_back(16);
  d.resize(d.size() + 14, 0);
  Bytes v = datagram_with(kCigiOpViewControl, 32);  // a view packet: handled elsewhere, not unsupported
  d.insert(d.end(), v.begin() + 24, v.end());
  d[3] = 5;  // load database 5
  const CigiHostPackets p = decode_cigi_host_packets(d);
  EXPECT_EQ(p.unsupported, (std::vector<std::uint8_t>{4, 35}));
  ASSERT_TRUE(p.database);
  EXPECT_EQ(*p.database, 5);
  EXPECT_TRUE(cigi_opcode_supported(kCigiOpEntityControl));
  EXPECT_FALSE(cigi_opcode_supported(4));
  // Nothing from a datagram without a good IG Control.
  d[0] = 2;
  EXPECT_TRUE(decode_cigi_host_packets(d).unsupported.empty());
}

TEST(CigiEnvironment, IgPacketsRoundTripBehindAStartOfFrame) {
  for (bool swap : {false, true}) {
    const auto sof = encode_cigi_start_of_frame(3, 2, 100, kCigiModeOperate, swap);
    Bytes d(sof.begin(), sof.end());
    const CigiPositionResponse pr{{0, 0, 0, 0}, {36.7, -118.06, 2500.25}, 1.5f, -4.0f, 250.0f};
    const CigiCollisionNotification cn{0, 4, false, 0, 0, 1234.5f};
    const CigiWeatherConditions wc{9, 0, 0, 5000.0f, 0, 0, 0, 0};
    const CigiIgMessage long_text{1001, std::string(200, 'x')};
    append_cigi_position_response(pr, swap, d);
    append_cigi_collision_notification(cn, swap, d);
    append_cigi_weather_conditions(wc, swap, d);
    append_cigi_ig_message({1000, "opcode 4 is not supported"}, swap, d);
    append_cigi_ig_message(long_text, swap, d);
    EXPECT_EQ(d.size(), 24u + 48 + 16 + 32 + 32 + 104);  // messages padded to 8, at most 104
    const auto p = decode_cigi_ig_packets(d);
    ASSERT_TRUE(p);
    EXPECT_EQ(p->positions.at(0), pr);
    EXPECT_EQ(p->collisions.at(0), cn);
    EXPECT_EQ(p->weather.at(0), wc);
    ASSERT_EQ(p->messages.size(), 2u);
    EXPECT_EQ(p->messages[0].text, "opcode 4 is not supported");
    EXPECT_EQ(p->messages[1].text.size(), 99u);  // cut to fit 104 bytes with its NUL
    d.pop_back();
    EXPECT_FALSE(decode_cigi_ig_packets(d));  // the last packet runs past the end
  }
}

}  // namespace
