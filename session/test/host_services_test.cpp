// HostServices: requests taken from CIGI datagrams, answered from the drawn
// surface; entity-relative points; periodic requests and cancellation; the
// per-frame budget and what waits for the next frame.

#include <gtest/gtest.h>

#include <cmath>
#include <variant>
#include <vector>

#include "session/host_services.h"
#include "io/wire/cigi.h"
#include "io/wire/cigi_queries.h"
#include "io/wire/native_query.h"
#include "session/scene_setup.h"
#include "session/test/ramp_host_services.h"

namespace {

using namespace ig::io::wire;
using ig::session::HostServices;
using ig::session::HostServicesOptions;

using Fixture = ig::session::test::RampHostServices;

template <typename... Packets>
std::vector<std::uint8_t> datagram(std::uint32_t host_frame, bool swap, const Packets&... packets) {
  std::vector<std::uint8_t> d = encode_cigi_host_datagram(host_frame, kCigiModeOperate, {}, swap);
  (d.insert(d.end(), packets.begin(), packets.end()), ...);
  return d;
}

ig::io::Pose level_pose(glm::dvec3 at, double heading_deg) {
  ig::io::Pose p;
  p.position = at;
  p.attitude = ig::io::attitude_from_hpr({heading_deg, 0.0, 0.0});
  return p;
}

TEST(HostServices, HotAndHatFromTheSurfaceBothOrders) {
  Fixture f;
  const ig::io::Pose own = level_pose({500, 600, 900}, 90);
  for (bool swap : {false, true}) {
    HatHotRequest r;
    r.id = 1;
    r.type = HatHotType::Extended;
    r.point = f.geodetic(333.0, 444.0, 1000.0);
    HatHotRequest out = r;
    out.id = 2;
    out.point = f.geodetic(-50.0, 444.0, 1000.0);  // west of the terrain
    f.services.take(datagram(17, swap, encode_cigi_hat_hot_request(r, swap), encode_cigi_hat_hot_request(out, swap)));
    const auto a = f.services.answer_frame(own);
    ASSERT_EQ(a.size(), 2u);
    const auto& h = std::get<HatHotResponse>(a[0]);
    EXPECT_TRUE(h.valid);
    EXPECT_EQ(h.host_frame, 17u);
    EXPECT_NEAR(h.hot_m, f.hf.sample_surface(333.0, 444.0), 1e-6);
    EXPECT_NEAR(h.hat_m, 1000.0 - h.hot_m, 1e-6);
    // The normal from the surface's slope there (one triangle within +-1 cm).
    const double gx = (f.hf.sample_surface(333.01, 444.0) - f.hf.sample_surface(332.99, 444.0)) / 0.02;
    const double gy = (f.hf.sample_surface(333.0, 444.01) - f.hf.sample_surface(333.0, 443.99)) / 0.02;
    EXPECT_NEAR(h.normal_elevation_deg, 90.0 - std::atan(std::hypot(gx, gy)) * 180 / M_PI, 1e-3);
    EXPECT_NEAR(h.normal_azimuth_deg, std::atan2(-gx, -gy) * 180 / M_PI, 1e-3);
    EXPECT_FALSE(std::get<HatHotResponse>(a[1]).valid);
  }
}

TEST(HostServices, EntityRelativePointsFollowTheOwnship) {
  Fixture f;
  // Heading east: body x (forward) is east, y (right) is south, z down.
  const ig::io::Pose own = level_pose({500, 600, 900}, 90);
  HatHotRequest r;
  r.type = HatHotType::Hat;
  r.coords = CigiCoords::Entity;
  r.point = {100.0, 50.0, 20.0};  // 100 m ahead, 50 m right, 20 m below
  f.services.take(datagram(1, false, encode_cigi_hat_hot_request(r, false)));
  LosVectorRequest v;  // straight down from the ownship
  v.id = 5;
  v.extended = true;
  v.source_coords = CigiCoords::Entity;
  v.response_coords = CigiCoords::Entity;
  v.elevation_deg = -90.0f;
  v.max_range_m = 5000.0f;
  HatHotRequest other = r;
  other.entity = 3;  // not known to the IG
  f.services.take(datagram(2, false, encode_cigi_los_vector_request(v, false), encode_cigi_hat_hot_request(other, false)));
  const auto a = f.services.answer_frame(own);
  ASSERT_EQ(a.size(), 3u);
  const auto& h = std::get<HatHotResponse>(a[0]);
  ASSERT_TRUE(h.valid);
  EXPECT_NEAR(h.hat_m, 880.0 - f.hf.sample_surface(600.0, 550.0), 1e-6);
  const auto& l = std::get<LosResponse>(a[1]);
  ASSERT_TRUE(l.valid && l.range_valid);
  EXPECT_FALSE(l.visible);
  EXPECT_NEAR(l.range_m, 900.0 - f.hf.sample_surface(500.0, 600.0), 1e-6);
  EXPECT_NEAR(l.point.x, 0.0, 1e-6);         // forward
  EXPECT_NEAR(l.point.z, l.range_m, 1e-6);  // down
  EXPECT_FALSE(std::get<HatHotResponse>(a[2]).valid);
  EXPECT_EQ(f.services.counters().invalid, 1u);
}

TEST(HostServices, LosSegmentHitAndClearInGeodetic) {
  Fixture f;
  const ig::io::Pose own = level_pose({500, 600, 900}, 0);
  LosSegmentRequest hit;
  hit.id = 7;
  hit.extended = true;
  hit.source = f.geodetic(200, 200, 1000);
  hit.destination = f.geodetic(1500, 1500, 0);  // under the terrain
  LosSegmentRequest clear = hit;
  clear.id = 8;
  clear.destination = f.geodetic(1500, 1500, 1200);
  f.services.take(datagram(3, true, encode_cigi_los_segment_request(hit, true), encode_cigi_los_segment_request(clear, true)));
  const auto a = f.services.answer_frame(own);
  ASSERT_EQ(a.size(), 2u);
  const auto& h = std::get<LosResponse>(a[0]);
  ASSERT_TRUE(h.valid && h.range_valid);
  EXPECT_FALSE(h.visible);
  // The hit point, back in local metres, lies on the surface and on the segment.
  const glm::dvec3 p = *ig::session::geodetic_placer(f.hf)(h.point.x, h.point.y, h.point.z);
  EXPECT_NEAR(p.z, f.hf.sample_surface(p.x, p.y), 1e-6);
  const glm::dvec3 from(200, 200, 1000), to(1500, 1500, 0);
  EXPECT_NEAR(glm::length(p - from), h.range_m, 1e-6);
  EXPECT_NEAR(glm::length(glm::cross(p - from, to - from)) / glm::length(to - from), 0.0, 1e-6);
  const auto& c = std::get<LosResponse>(a[1]);
  EXPECT_TRUE(c.valid);
  EXPECT_TRUE(c.visible);
  EXPECT_FALSE(c.range_valid);
}

TEST(HostServices, PeriodicRequestsUntilCancelled) {
  Fixture f;
  const ig::io::Pose own = level_pose({500, 600, 900}, 0);
  HatHotRequest r;
  r.id = 9;
  r.type = HatHotType::Hot;
  r.update_period = 3;
  r.point = f.geodetic(300, 300, 0);
  f.services.take(datagram(1, false, encode_cigi_hat_hot_request(r, false)));
  std::vector<int> answered_frames;
  for (int frame = 0; frame < 10; ++frame)
    if (!f.services.answer_frame(own).empty()) answered_frames.push_back(frame);
  EXPECT_EQ(answered_frames, (std::vector<int>{0, 3, 6, 9}));
  EXPECT_EQ(f.services.periodic(), 1u);
  r.update_period = 0;  // cancel: one last answer, then none
  f.services.take(datagram(2, false, encode_cigi_hat_hot_request(r, false)));
  EXPECT_EQ(f.services.answer_frame(own).size(), 1u);
  for (int frame = 0; frame < 6; ++frame) EXPECT_TRUE(f.services.answer_frame(own).empty());
  EXPECT_EQ(f.services.periodic(), 0u);
  EXPECT_EQ(f.services.counters().cancelled, 1u);
  EXPECT_EQ(f.services.counters().periodic_answers, 4u);
}

TEST(HostServices, BudgetDefersTheRestToLaterFrames) {
  HostServicesOptions o;
  o.max_hat_hot_per_frame = 2000;
  o.max_los_per_frame = 10;
  o.max_pending = 6000;
  Fixture f(o);
  const ig::io::Pose own = level_pose({500, 600, 900}, 0);
  HatHotRequest r;
  r.point = f.geodetic(300, 300, 500);
  LosVectorRequest v;
  v.source = f.geodetic(300, 300, 500);
  v.elevation_deg = -45.0f;
  v.max_range_m = 3000.0f;
  for (int k = 0; k < 7000; ++k) {  // 7000 HOT (1000 over the queue) and 25 LOS
    r.id = std::uint16_t(k);
    if (k < 25) {
      v.id = std::uint16_t(k);
      f.services.take(datagram(1, false, encode_cigi_hat_hot_request(r, false), encode_cigi_los_vector_request(v, false)));
    } else {
      f.services.take(datagram(1, false, encode_cigi_hat_hot_request(r, false)));
    }
  }
  EXPECT_EQ(f.services.counters().dropped.at("queue-full"), 1025u);
  std::vector<std::size_t> per_frame;
  while (f.services.pending() > 0) per_frame.push_back(f.services.answer_frame(own).size());
  // In arrival order: a frame ends at the first request over its budget.
  ASSERT_GE(per_frame.size(), 3u);
  for (std::size_t n : per_frame) EXPECT_LE(n, 2010u);
  std::size_t total = 0;
  for (std::size_t n : per_frame) total += n;
  EXPECT_EQ(total, 6000u);
  EXPECT_EQ(f.services.counters().deferred, 6000u - per_frame[0]);
  // Every response of a frame fits one datagram with its Start Of Frame.
  f.services.take(datagram(1, false, encode_cigi_hat_hot_request(r, false)));
  const auto d = f.services.frame_datagram(encode_cigi_start_of_frame(1, 1, 0, kCigiModeOperate, false), own);
  const auto back = decode_cigi_responses(d);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->size(), 1u);
}

TEST(HostServices, NativeQueriesAnsweredAtOnceWithinTheBudget) {
  HostServicesOptions o;
  o.max_hat_hot_per_frame = 3;
  Fixture f(o);
  const ig::io::Pose own = level_pose({500, 600, 900}, 0);
  NativeQuery q;
  q.kind = NativeQueryKind::Height;
  q.geodetic = true;
  q.id = 42;
  q.a = f.geodetic(333.0, 444.0, 1000.0);
  const auto a = f.services.answer_native(encode_native_query(q));
  ASSERT_TRUE(a);
  const auto h = decode_native_answer(*a);
  ASSERT_TRUE(h && h->valid);
  EXPECT_EQ(h->id, 42u);
  EXPECT_NEAR(h->hot_or_range_m, f.hf.sample_surface(333.0, 444.0), 1e-6);
  EXPECT_NEAR(h->hat_m, 1000.0 - h->hot_or_range_m, 1e-6);
  EXPECT_NEAR(h->point.x, q.a.x, 1e-9);  // latitude back
  // Local frame, straight down: the range is the height above the surface.
  NativeQuery v;
  v.kind = NativeQueryKind::LosVector;
  v.a = {700, 800, 2000};
  v.b = {0, 0, -5};
  v.max_range_m = INFINITY;
  const auto l = decode_native_answer(*f.services.answer_native(encode_native_query(v)));
  ASSERT_TRUE(l && l->valid && l->hit);
  EXPECT_NEAR(l->hot_or_range_m, 2000.0 - f.hf.sample_surface(700, 800), 1e-9);
  // Three HAT/HOT per frame: the fourth is refused until the frame ends.
  EXPECT_TRUE(f.services.answer_native(encode_native_query(q)));
  EXPECT_TRUE(f.services.answer_native(encode_native_query(q)));
  EXPECT_FALSE(f.services.answer_native(encode_native_query(q)));
  EXPECT_EQ(f.services.counters().dropped.at("native-over-budget"), 1u);
  f.services.answer_frame(own);
  EXPECT_TRUE(f.services.answer_native(encode_native_query(q)));
  // Outside: valid clear; malformed: counted, no answer.
  q.a = f.geodetic(-100.0, 10.0, 0.0);
  EXPECT_FALSE(decode_native_answer(*f.services.answer_native(encode_native_query(q)))->valid);
  auto bad = encode_native_query(q);
  bad[30] ^= 1;
  EXPECT_FALSE(f.services.answer_native(bad));
  EXPECT_EQ(f.services.counters().dropped.at("native-bad-crc"), 1u);
}

TEST(HostServices, MalformedRequestsCountedByReason) {
  Fixture f;
  HatHotRequest r;
  r.point = {NAN, 0, 0};
  auto bad = encode_cigi_hat_hot_request(r, false);
  std::vector<std::uint8_t> d = datagram(1, false, bad);
  f.services.take(d);
  d.resize(d.size() - 4);  // truncated
  f.services.take(d);
  EXPECT_EQ(f.services.counters().dropped.at("non-finite"), 1u);
  EXPECT_EQ(f.services.counters().dropped.at("truncated"), 1u);
  EXPECT_EQ(f.services.pending(), 0u);
}

}  // namespace
