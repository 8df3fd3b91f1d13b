// HostEnvironment: the time of day, visibility and cloud layers a host sets, Position
// Requests (one-shot, continuous, unknown objects), collision segments cast
// against the terrain, unsupported opcodes answered once, and a reset.

#include <gtest/gtest.h>

#include <vector>

#include "io/wire/cigi.h"
#include "io/wire/cigi_environment.h"
#include "session/host_environment.h"
#include "session/scene_setup.h"
#include "session/test/ramp_host_services.h"

namespace {

using namespace ig::io::wire;
using ig::session::HostEnvironment;

struct Fixture : ig::session::test::RampHostServices {
  HostEnvironment env{services, ig::session::local_to_geodetic(hf), 60000.0};
  ig::io::Pose own;
  Fixture() {
    own.position = {500, 600, 900};
    own.attitude = ig::io::attitude_from_hpr({90.0, 0.0, 0.0});
  }
  template <typename... Packets>
  void send(std::uint32_t mode, const Packets&... packets) {
    std::vector<std::uint8_t> d = encode_cigi_host_datagram(1, mode, {}, false);
    (d.insert(d.end(), packets.begin(), packets.end()), ...);
    env.take(d);
  }
  CigiIgPackets frame() {
    const auto sof = encode_cigi_start_of_frame(1, 1, 0, kCigiModeOperate, false);
    std::vector<std::uint8_t> d(sof.begin(), sof.end());
    const ig::io::Pose view = own;
    env.append_frame_packets(own, std::span(&view, 1), 5000.0, d, kCigiMaxDatagram);
    return *decode_cigi_ig_packets(d);
  }
};

TEST(HostEnvironment, TimeOfDayAndVisibilityAreChangesForTheNextFrame) {
  Fixture f;
  const ig::options::UtcDateTime today{2026, 11, 26, 1, 2, 3.0};
  EXPECT_FALSE(f.env.changes(900.0, [&] { return today; }).time_utc);
  CigiCelestialSphere c;
  c.hour = 18;
  c.minute = 30;  // date not valid: today's date is kept
  CigiAtmosphere a;
  a.visibility_m = 5000.0f;
  f.send(kCigiModeOperate, encode_cigi_celestial(c, false), encode_cigi_atmosphere(a, false));
  const auto ch = f.env.changes(900.0, [&] { return today; });
  ASSERT_TRUE(ch.time_utc && ch.visibility_m);
  EXPECT_EQ(*ch.time_utc, (ig::options::UtcDateTime{2026, 11, 26, 18, 30, 0.0}));
  EXPECT_FALSE(ch.clock_runs);  // ephemeris off: the sun holds
  EXPECT_EQ(*ch.visibility_m, 5000.0);
  EXPECT_FALSE(f.env.changes(900.0, [&] { return today; }).visibility_m);  // applied once
}

TEST(HostEnvironment, AGlobalWeatherLayerSetsTheVisibilityInsideItsBand) {
  Fixture f;
  const ig::options::UtcDateTime today;
  CigiWeatherControl fog;
  fog.layer = 2;
  fog.enabled = true;
  fog.visibility_m = 800.0f;
  fog.base_m = 1000.0f;
  fog.thickness_m = 500.0f;
  CigiWeatherControl regional = fog;
  regional.scope = 1;  // regional weather: counted, not drawn
  regional.layer = 3;
  regional.visibility_m = 10.0f;
  f.send(kCigiModeOperate, encode_cigi_weather(fog, false), encode_cigi_weather(regional, false));
  EXPECT_FALSE(f.env.changes(900.0, [&] { return today; }).visibility_m);  // below the layer: the IG's own 60 km
  EXPECT_EQ(f.env.changes(1200.0, [&] { return today; }).visibility_m, 800.0);  // inside it
  EXPECT_FALSE(f.env.changes(1300.0, [&] { return today; }).visibility_m);     // still inside: no change
  EXPECT_EQ(f.env.changes(1600.0, [&] { return today; }).visibility_m, 60000.0);  // above: back to the IG's own
  CigiAtmosphere a;
  a.visibility_m = 5000.0f;
  fog.enabled = false;  // the layer removed
  f.send(kCigiModeOperate, encode_cigi_atmosphere(a, false), encode_cigi_weather(fog, false));
  EXPECT_EQ(f.env.changes(1200.0, [&] { return today; }).visibility_m, 5000.0);
}

TEST(HostEnvironment, PositionRequestsOneShotContinuousAndUnknown) {
  Fixture f;
  f.send(kCigiModeOperate, encode_cigi_position_request({{0, 0, kCigiObjectEntity, 0}, false}, false),
         encode_cigi_position_request({{0, 0, kCigiObjectView, 0}, true}, false),
         encode_cigi_position_request({{9, 0, kCigiObjectEntity, 0}, false}, false));
  const CigiIgPackets first = f.frame();
  ASSERT_EQ(first.positions.size(), 2u);  // entity 0 and view 0; entity 9 is not known
  const auto geo = *ig::session::local_to_geodetic(f.hf)(f.own.position);
  EXPECT_EQ(first.positions[0].position, geo);
  EXPECT_NEAR(first.positions[0].yaw_deg, 90.0f, 1e-4);
  ASSERT_EQ(first.messages.size(), 1u);
  EXPECT_NE(first.messages[0].text.find("entity 9"), std::string::npos);
  EXPECT_EQ(f.frame().positions.size(), 1u);  // the continuous one only
  f.send(kCigiModeOperate, encode_cigi_position_request({{0, 0, kCigiObjectView, 0}, false}, false));
  EXPECT_EQ(f.frame().positions.size(), 1u);  // the one-shot that ends it
  EXPECT_TRUE(f.frame().positions.empty());
}

TEST(HostEnvironment, CollisionSegmentsCrossingTheGroundAreNotified) {
  Fixture f;
  const double hat = f.own.position.z - f.hf.sample_surface(f.own.position.x, f.own.position.y);
  f.send(kCigiModeOperate, encode_cigi_collision_segment({0, 1, true, {0, 0, 0}, {0, 0, hat + 20}, 0}, false),
         encode_cigi_collision_segment({0, 2, true, {0, 0, 0}, {0, 0, hat - 20}, 0}, false),
         encode_cigi_collision_segment({3, 3, true, {0, 0, 0}, {0, 0, hat + 20}, 0}, false));
  for (int k = 0; k < 2; ++k) {
    const CigiIgPackets p = f.frame();
    ASSERT_EQ(p.collisions.size(), 1u);
    EXPECT_EQ(p.collisions[0].segment, 1);
    EXPECT_NEAR(p.collisions[0].distance_m, hat, 0.05);
  }
  // Entity 3 is unknown to the IG: its segment is kept, not cast.
  EXPECT_EQ(f.env.counters().rejected.at("segment-of-unknown-entity"), 2u);
  // Once the IG has entity 3 (here where the ownship is), its segment is cast from it.
  f.env.set_entity_lookup([&](std::uint16_t id, std::optional<std::uint8_t>) -> std::optional<ig::io::Pose> {
    if (id == 3) return f.own;
    return std::nullopt;
  });
  const CigiIgPackets with_entity = f.frame();
  ASSERT_EQ(with_entity.collisions.size(), 2u);
  EXPECT_EQ(with_entity.collisions[1].entity, 3);
  EXPECT_NEAR(with_entity.collisions[1].distance_m, hat, 0.05);
  // A reset drops the host's segments.
  f.send(kCigiModeStandby);
  EXPECT_EQ(f.env.ig_mode(), kCigiModeStandby);
  EXPECT_TRUE(f.frame().collisions.empty());
  f.send(kCigiModeOperate);
  EXPECT_EQ(f.env.ig_mode(), kCigiModeOperate);
}

TEST(HostEnvironment, UnsupportedOpcodesAreCountedAndAnsweredOnce) {
  Fixture f;
  const std::array<std::uint8_t, 32> component{4, 32};
  f.send(kCigiModeOperate, component, component);
  f.send(kCigiModeOperate, component);
  EXPECT_EQ(f.env.counters().unsupported.at(4), 3u);
  EXPECT_EQ(f.frame().messages.size(), 1u);
  EXPECT_TRUE(f.frame().messages.empty());
  CigiEnvironmentRequest r;
  r.types = kCigiConditionsWeather;
  r.id = 5;
  f.send(kCigiModeOperate, encode_cigi_environment_request(r, false));
  const CigiIgPackets p = f.frame();
  ASSERT_EQ(p.weather.size(), 1u);
  EXPECT_EQ(p.weather[0].request_id, 5);
  EXPECT_EQ(p.weather[0].visibility_m, 5000.0f);
  EXPECT_EQ(f.env.summary()["unsupported"]["4"], 3);
}

// The Weather Conditions Response echoes what Atmosphere Control set; before
// any, the standard atmosphere at the request's altitude (not 0 hPa).
TEST(HostEnvironment, WeatherConditionsEchoTheAtmosphere) {
  Fixture f;
  CigiEnvironmentRequest r;
  r.types = kCigiConditionsWeather;
  r.id = 7;
  r.point = {36.7, -118.06, 1500.0};
  f.send(kCigiModeOperate, encode_cigi_environment_request(r, false));
  CigiIgPackets p = f.frame();
  ASSERT_EQ(p.weather.size(), 1u);
  // ICAO standard atmosphere at 1 500 m: 5.25 C, 845.6 hPa.
  EXPECT_NEAR(p.weather[0].air_temp_c, 5.25f, 1e-3);
  EXPECT_NEAR(p.weather[0].pressure_hpa, 845.6f, 0.1);
  EXPECT_EQ(p.weather[0].humidity_pct, 0);
  const CigiAtmosphere set{true, 63, -4.5f, 8000.0f, 12.0f, -1.5f, 250.0f, 1002.5f};
  f.send(kCigiModeOperate, encode_cigi_atmosphere(set, false), encode_cigi_environment_request(r, false));
  p = f.frame();
  ASSERT_EQ(p.weather.size(), 1u);
  const CigiWeatherConditions& w = p.weather[0];
  EXPECT_EQ(w.request_id, 7);
  EXPECT_EQ(w.humidity_pct, 63);
  EXPECT_EQ(w.air_temp_c, -4.5f);
  EXPECT_EQ(w.horizontal_wind_mps, 12.0f);
  EXPECT_EQ(w.vertical_wind_mps, -1.5f);
  EXPECT_EQ(w.wind_direction_deg, 250.0f);
  EXPECT_EQ(w.pressure_hpa, 1002.5f);
}

CigiWeatherControl cloud_layer(std::uint8_t layer, std::uint8_t type, float coverage_pct, float base_m) {
  CigiWeatherControl w;
  w.layer = layer;
  w.enabled = true;
  w.cloud_type = type;
  w.coverage_pct = coverage_pct;
  w.base_m = base_m;
  w.thickness_m = 300.0f;
  return w;
}

TEST(HostEnvironment, WeatherControlCloudLayersBecomeTheScenesClouds) {
  Fixture f;
  const ig::options::UtcDateTime today;
  CigiWeatherControl st = cloud_layer(1, 10, 100.0f, 1500.0f);  // stratus
  st.visibility_m = 80.0f;
  st.transition_band_m = 40.0f;
  st.horizontal_wind_mps = 10.0f;
  st.wind_direction_deg = 270.0f;  // from the west
  st.scud = true;
  st.scud_frequency_pct = 30.0f;
  const CigiWeatherControl cu = cloud_layer(2, 7, 50.0f, 2500.0f);  // cumulus
  f.send(kCigiModeOperate, encode_cigi_weather(st, false), encode_cigi_weather(cu, false));
  // Inside the stratus layer: its visibility is drawn by the clouds, not the fog.
  auto ch = f.env.changes(1600.0, [&] { return today; });
  EXPECT_FALSE(ch.visibility_m);
  ASSERT_TRUE(ch.clouds);
  ASSERT_EQ(ch.clouds->size(), 2u);
  const auto& a = (*ch.clouds)[0];
  EXPECT_EQ(a.id, 1);
  EXPECT_EQ(a.type, ig::options::CloudType::Stratus);
  EXPECT_DOUBLE_EQ(a.coverage, 1.0);
  EXPECT_DOUBLE_EQ(a.base_m, 1500.0);
  EXPECT_DOUBLE_EQ(a.thickness_m, 300.0);
  EXPECT_DOUBLE_EQ(a.transition_m, 40.0);
  EXPECT_DOUBLE_EQ(a.visibility_m, 80.0);
  EXPECT_NEAR(a.scud, 0.3, 1e-6);
  EXPECT_NEAR(a.wind_mps.x, 10.0, 1e-5);  // drifting east
  EXPECT_NEAR(a.wind_mps.y, 0.0, 1e-5);
  EXPECT_EQ((*ch.clouds)[1].type, ig::options::CloudType::Cumulus);
  EXPECT_DOUBLE_EQ((*ch.clouds)[1].coverage, 0.5);
  EXPECT_FALSE(f.env.changes(1600.0, [&] { return today; }).clouds);  // applied once
  st.enabled = false;  // the stratus removed
  f.send(kCigiModeOperate, encode_cigi_weather(st, false));
  ch = f.env.changes(1600.0, [&] { return today; });
  ASSERT_TRUE(ch.clouds);
  ASSERT_EQ(ch.clouds->size(), 1u);
  EXPECT_EQ(ch.clouds->front().id, 2);
}

TEST(HostEnvironment, BadCloudLayersAreCountedAndRefused) {
  Fixture f;
  const ig::options::UtcDateTime today;
  CigiWeatherControl negative = cloud_layer(2, 10, 50.0f, 1500.0f);
  negative.thickness_m = -10.0f;
  const CigiWeatherControl too_high = cloud_layer(3, 5, 50.0f, 200000.0f);
  const CigiWeatherControl other = cloud_layer(4, 12, 50.0f, 1500.0f);  // 11-15: "other"
  f.send(kCigiModeOperate, encode_cigi_weather(cloud_layer(1, 10, 150.0f, 1500.0f), false),
         encode_cigi_weather(negative, false), encode_cigi_weather(too_high, false), encode_cigi_weather(other, false),
         encode_cigi_weather(cloud_layer(5, 7, 25.0f, 2000.0f), false));
  const auto ch = f.env.changes(900.0, [&] { return today; });
  ASSERT_TRUE(ch.clouds);
  ASSERT_EQ(ch.clouds->size(), 1u);  // only the good cumulus
  EXPECT_EQ(ch.clouds->front().id, 5);
  const auto summary = f.env.summary();
  EXPECT_EQ(summary["rejected"]["weather-cloud-layer"], 3);
  EXPECT_EQ(summary["rejected"]["weather-cloud-type"], 1);
  std::string texts;
  for (const auto& m : f.frame().messages) texts += m.text + "\n";
  EXPECT_NE(texts.find("layer 1: coverage outside 0-100 %"), std::string::npos) << texts;
  EXPECT_NE(texts.find("layer 2: negative thickness"), std::string::npos) << texts;
  EXPECT_NE(texts.find("layer 3: top above 100 km"), std::string::npos) << texts;
  EXPECT_NE(texts.find("cloud type 12 (other) is not drawn"), std::string::npos) << texts;
  // The scene's own refusals are counted with the host's.
  f.env.refuse("weather-cloud-layer", "cloud layer 9: more than 4 cloud layers");
  EXPECT_EQ(f.env.summary()["rejected"]["weather-cloud-layer"], 4);
}

}  // namespace
