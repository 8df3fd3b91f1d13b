// CIGI 3.3 HAT/HOT and LOS requests and responses: hand-written bytes in
// both orders (independent of the encoders), round trips, every reject
// reason, and mutated datagrams.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <variant>
#include <vector>

#include "io/wire/cigi.h"
#include "io/wire/cigi_queries.h"
#include "io/test/wire_test_support.h"

namespace {

using namespace ig::io::wire;
using Bytes = std::vector<std::uint8_t>;

// An IG Control (host frame 7) in the given order, hand-written.
Bytes ig_control(bool big) {
  Bytes b(24, 0);
  b[0] = 1;
  b[1] = 24;
  b[2] = 3;
  b[4] = 0x31;  // operate, minor 3
  if (big) {
    b[6] = 0x80;
    b[11] = 7;
  } else {
    b[7] = 0x80;
    b[8] = 7;
  }
  return b;
}

void put(Bytes& b, std::size_t at, std::uint64_t v, int n, bool big) {
  for (int k = 0; k < n; ++k) b[at + std::size_t(big ? n - 1 - k : k)] = std::uint8_t(v >> (8 * k));
}
void put_f64(Bytes& b, std::size_t at, double v, bool big) { put(b, at, std::bit_cast<std::uint64_t>(v), 8, big); }
void put_f32(Bytes& b, std::size_t at, float v, bool big) { put(b, at, std::bit_cast<std::uint32_t>(v), 4, big); }

Bytes hand_hat_hot(bool big, std::uint8_t flags, double lat, double lon, double alt) {
  Bytes b(32, 0);
  b[0] = 24;
  b[1] = 32;
  put(b, 2, 0x1234, 2, big);
  b[4] = flags;
  b[5] = 3;  // update period
  put(b, 6, 0x0102, 2, big);
  put_f64(b, 8, lat, big);
  put_f64(b, 16, lon, big);
  put_f64(b, 24, alt, big);
  return b;
}

Bytes cat(Bytes a, const Bytes& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}
template <std::size_t N>
Bytes cat(Bytes a, const std::array<std::uint8_t, N>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(WireCigiQueries, HandmadeHatHotRequestBothOrders) {
  for (bool big : {true, false}) {
    SCOPED_TRACE(big ? "big-endian" : "little-endian");
    const auto r = decode_cigi_requests(cat(ig_control(big), hand_hat_hot(big, 0x06, 37.5, -118.25, 3000.5)));
    ASSERT_TRUE(r.host_frame);
    EXPECT_EQ(*r.host_frame, 7u);
    EXPECT_EQ(r.byte_swapped, big != (std::endian::native == std::endian::big));
    ASSERT_EQ(r.requests.size(), 1u);
    EXPECT_TRUE(r.rejects.empty());
    const auto& h = std::get<HatHotRequest>(r.requests[0]);
    EXPECT_EQ(h.id, 0x1234);
    EXPECT_EQ(h.type, HatHotType::Extended);  // flags bits 0-1 = 2
    EXPECT_EQ(h.coords, CigiCoords::Entity);  // bit 2
    EXPECT_EQ(h.update_period, 3);
    EXPECT_EQ(h.entity, 0x0102);
    EXPECT_EQ(h.point.x, 37.5);
    EXPECT_EQ(h.point.y, -118.25);
    EXPECT_EQ(h.point.z, 3000.5);
  }
}

TEST(WireCigiQueries, HandmadeLosRequestsBothOrders) {
  for (bool big : {true, false}) {
    SCOPED_TRACE(big ? "big-endian" : "little-endian");
    Bytes seg(64, 0);
    seg[0] = 25;
    seg[1] = 64;
    put(seg, 2, 9, 2, big);
    seg[4] = 0x1d;  // extended, dest entity coords, response entity coords, dest entity valid
    seg[5] = 128;
    put_f64(seg, 8, 37.0, big);
    put_f64(seg, 16, -118.0, big);
    put_f64(seg, 24, 4000.0, big);
    put_f64(seg, 32, 10.0, big);
    put_f64(seg, 40, 20.0, big);
    put_f64(seg, 48, 30.0, big);
    put(seg, 56, 0xdeadbeef, 4, big);
    seg[60] = 2;
    put(seg, 62, 77, 2, big);
    Bytes vec(56, 0);
    vec[0] = 26;
    vec[1] = 56;
    put(vec, 2, 10, 2, big);
    vec[4] = 0x02;  // basic, source entity, response geodetic
    put_f32(vec, 8, 45.0f, big);
    put_f32(vec, 12, -10.0f, big);
    put_f32(vec, 16, 5.0f, big);
    put_f32(vec, 20, 9000.0f, big);
    put_f64(vec, 24, 1.0, big);
    put_f64(vec, 32, 2.0, big);
    put_f64(vec, 40, -3.0, big);
    vec[52] = 0;
    const auto r = decode_cigi_requests(cat(cat(ig_control(big), seg), vec));
    ASSERT_EQ(r.requests.size(), 2u);
    const auto& s = std::get<LosSegmentRequest>(r.requests[0]);
    EXPECT_EQ(s.id, 9);
    EXPECT_TRUE(s.extended);
    EXPECT_EQ(s.source_coords, CigiCoords::Geodetic);
    EXPECT_EQ(s.destination_coords, CigiCoords::Entity);
    EXPECT_EQ(s.response_coords, CigiCoords::Entity);
    EXPECT_TRUE(s.destination_entity_valid);
    EXPECT_EQ(s.alpha_threshold, 128);
    EXPECT_EQ(s.source, glm::dvec3(37.0, -118.0, 4000.0));
    EXPECT_EQ(s.destination, glm::dvec3(10.0, 20.0, 30.0));
    EXPECT_EQ(s.material_mask, 0xdeadbeefu);
    EXPECT_EQ(s.update_period, 2);
    EXPECT_EQ(s.destination_entity, 77);
    const auto& v = std::get<LosVectorRequest>(r.requests[1]);
    EXPECT_EQ(v.id, 10);
    EXPECT_FALSE(v.extended);
    EXPECT_EQ(v.source_coords, CigiCoords::Entity);
    EXPECT_EQ(v.response_coords, CigiCoords::Geodetic);
    EXPECT_EQ(v.azimuth_deg, 45.0f);
    EXPECT_EQ(v.elevation_deg, -10.0f);
    EXPECT_EQ(v.min_range_m, 5.0f);
    EXPECT_EQ(v.max_range_m, 9000.0f);
    EXPECT_EQ(v.source, glm::dvec3(1.0, 2.0, -3.0));
  }
}

TEST(WireCigiQueries, RoundTripRandomRequestsBothOrders) {
  std::mt19937_64 rng(24);
  for (int k = 0; k < 5000; ++k) {
    const bool swap = k & 1;
    HatHotRequest h;
    h.id = std::uint16_t(rng());
    h.type = HatHotType(rng() % 3);
    h.coords = CigiCoords(rng() % 2);
    h.update_period = std::uint8_t(rng());
    h.entity = std::uint16_t(rng());
    h.point = {wire_test::uniform(rng, -90, 90), wire_test::uniform(rng, -180, 180), wire_test::uniform(rng, -400, 9000)};
    LosSegmentRequest s;
    s.id = std::uint16_t(rng());
    s.extended = rng() & 1;
    s.response_coords = CigiCoords(rng() % 2);
    s.source = {wire_test::uniform(rng, -90, 90), wire_test::uniform(rng, -180, 180), 100};
    s.destination = {wire_test::uniform(rng, -90, 90), wire_test::uniform(rng, -180, 180), 200};
    s.material_mask = std::uint32_t(rng());
    s.update_period = std::uint8_t(rng());
    LosVectorRequest v;
    v.id = std::uint16_t(rng());
    v.extended = rng() & 1;
    v.azimuth_deg = float(wire_test::uniform(rng, -180, 180));
    v.elevation_deg = float(wire_test::uniform(rng, -90, 90));
    v.min_range_m = float(wire_test::uniform(rng, 0, 100));
    v.max_range_m = v.min_range_m + float(wire_test::uniform(rng, 0, 1e5));
    v.source = {wire_test::uniform(rng, -90, 90), wire_test::uniform(rng, -180, 180), 5};
    Bytes d = encode_cigi_host_datagram(std::uint32_t(k), kCigiModeOperate, {}, swap);
    d = cat(cat(cat(d, encode_cigi_hat_hot_request(h, swap)), encode_cigi_los_segment_request(s, swap)),
            encode_cigi_los_vector_request(v, swap));
    const auto r = decode_cigi_requests(d);
    ASSERT_EQ(r.requests.size(), 3u);
    EXPECT_EQ(r.byte_swapped, swap);
    EXPECT_TRUE(std::get<HatHotRequest>(r.requests[0]) == h) << "HAT/HOT request " << k;
    EXPECT_TRUE(std::get<LosSegmentRequest>(r.requests[1]) == s) << "LOS segment request " << k;
    EXPECT_TRUE(std::get<LosVectorRequest>(r.requests[2]) == v) << "LOS vector request " << k;
  }
}

TEST(WireCigiQueries, RejectsByReason) {
  const bool big = true;
  auto one = [&](const Bytes& packet) { return decode_cigi_requests(cat(ig_control(big), packet)); };
  auto only_reject = [](const CigiRequests& r) {
    EXPECT_TRUE(r.requests.empty());
    return r.rejects.size() == 1 ? std::optional(r.rejects[0]) : std::nullopt;
  };
  Bytes wrong = hand_hat_hot(big, 0, 1, 2, 3);
  wrong[1] = 24;  // wrong size (and the rest is skipped by it)
  wrong.resize(24);
  EXPECT_EQ(only_reject(one(wrong)), QueryReject::WrongSize);
  Bytes cut = hand_hat_hot(big, 0, 1, 2, 3);
  cut.resize(20);  // size says 32, 20 there
  EXPECT_EQ(only_reject(one(cut)), QueryReject::Truncated);
  EXPECT_EQ(only_reject(one(hand_hat_hot(big, 3, 1, 2, 3))), QueryReject::BadType);
  EXPECT_EQ(only_reject(one(hand_hat_hot(big, 0, NAN, 2, 3))), QueryReject::NonFinite);
  EXPECT_EQ(only_reject(one(hand_hat_hot(big, 0, 91, 2, 3))), QueryReject::OutOfRange);
  EXPECT_EQ(only_reject(one(hand_hat_hot(big, 0, 1, 2, 2e6))), QueryReject::OutOfRange);
  EXPECT_EQ(only_reject(one(hand_hat_hot(big, 4, 1e8, 0, 0))), QueryReject::OutOfRange);  // entity offset
  LosVectorRequest v;
  v.min_range_m = 10;
  v.max_range_m = 5;
  EXPECT_EQ(only_reject(decode_cigi_requests(cat(ig_control(false), encode_cigi_los_vector_request(v, false)))),
            QueryReject::OutOfRange);
  v.max_range_m = INFINITY;
  EXPECT_EQ(only_reject(decode_cigi_requests(cat(ig_control(false), encode_cigi_los_vector_request(v, false)))),
            QueryReject::NonFinite);
  // A good request after a bad one is still taken; unknown opcodes are skipped silently.
  Bytes other(12, 0);
  other[0] = 200;
  other[1] = 12;
  const auto mixed = decode_cigi_requests(cat(cat(cat(ig_control(big), hand_hat_hot(big, 3, 1, 2, 3)), other),
                                              hand_hat_hot(big, 1, 1, 2, 3)));
  EXPECT_EQ(mixed.requests.size(), 1u);
  EXPECT_EQ(mixed.rejects.size(), 1u);
  // Overflow past the limit: counted, not rejected.
  Bytes many = ig_control(big);
  for (int k = 0; k < 10; ++k) many = cat(many, hand_hat_hot(big, 1, 1, 2, 3));
  const auto capped = decode_cigi_requests(many, CigiRequestLimits{4});
  EXPECT_EQ(capped.requests.size(), 4u);
  EXPECT_EQ(capped.overflow, 6u);
  // Not a host datagram: nothing at all.
  EXPECT_FALSE(decode_cigi_requests(hand_hat_hot(big, 1, 1, 2, 3)).host_frame);
  Bytes bad_magic = cat(ig_control(big), hand_hat_hot(big, 1, 1, 2, 3));
  bad_magic[6] = 0x12;
  EXPECT_TRUE(decode_cigi_requests(bad_magic).requests.empty());
}

// Responses against hand-computed big-endian bytes.
TEST(WireCigiQueries, ResponseLayouts) {
  const bool swap = std::endian::native != std::endian::big;  // write big-endian
  Bytes b;
  HatHotResponse h;
  h.id = 0x0a0b;
  h.valid = true;
  h.type = HatHotType::Hot;
  h.host_frame = 0x1234567f;
  h.hot_m = 1.5;
  append_cigi_response(h, swap, b);
  EXPECT_EQ(b, (Bytes{102, 16, 0x0a, 0x0b, 0xf3, 0, 0, 0, 0x3f, 0xf8, 0, 0, 0, 0, 0, 0}));
  b.clear();
  h.extended = true;
  h.hat_m = -2.0;
  h.material = 5;
  h.normal_azimuth_deg = 1.0f;
  h.normal_elevation_deg = 90.0f;
  append_cigi_response(h, swap, b);
  ASSERT_EQ(b.size(), 40u);
  EXPECT_EQ(b[0], 103);
  EXPECT_EQ(b[4], 0xf1);  // valid, LSN 15
  EXPECT_EQ((Bytes(b.begin() + 8, b.begin() + 10)), (Bytes{0xc0, 0x00}));   // HAT -2
  EXPECT_EQ((Bytes(b.begin() + 16, b.begin() + 18)), (Bytes{0x3f, 0xf8}));  // HOT 1.5
  EXPECT_EQ(b[27], 5);
  EXPECT_EQ((Bytes(b.begin() + 28, b.begin() + 36)), (Bytes{0x3f, 0x80, 0, 0, 0x42, 0xb4, 0, 0}));
  b.clear();
  LosResponse l;
  l.id = 3;
  l.valid = true;
  l.visible = true;
  l.response_count = 1;
  l.host_frame = 2;
  l.range_m = 0;
  append_cigi_response(l, swap, b);
  EXPECT_EQ(b, (Bytes{104, 16, 0, 3, 0x25, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}));
  b.clear();
  l.extended = true;
  l.visible = false;
  l.range_valid = true;
  l.range_m = 2.0;
  l.point = {1.0, -1.0, 0.5};
  append_cigi_response(l, swap, b);
  ASSERT_EQ(b.size(), 56u);
  EXPECT_EQ(b[0], 105);
  EXPECT_EQ(b[4], 0x25);  // valid, range valid, LSN 2
  EXPECT_EQ(b[8], 0x40);
  EXPECT_EQ(b[16], 0x3f);
  EXPECT_EQ(b[24], 0xbf);
  EXPECT_EQ(b[32], 0x3f);
  EXPECT_EQ(b[33], 0xe0);
}

TEST(WireCigiQueries, ResponsesRoundTripBothOrders) {
  for (bool swap : {false, true}) {
    const auto sof = encode_cigi_start_of_frame(1, 2, 3, kCigiModeOperate, swap);
    Bytes d(sof.begin(), sof.end());
    HatHotResponse h;
    h.id = 11;
    h.valid = true;
    h.type = HatHotType::Hat;
    h.hat_m = 123.25;
    h.host_frame = 9;
    append_cigi_response(h, swap, d);
    HatHotResponse x = h;
    x.extended = true;
    x.hot_m = 2000.5;
    x.normal_azimuth_deg = -45.0f;
    x.normal_elevation_deg = 80.0f;
    append_cigi_response(x, swap, d);
    LosResponse l;
    l.id = 12;
    l.valid = true;
    l.range_valid = true;
    l.extended = true;
    l.range_m = 1234.5;
    l.point = {37.1, -118.2, 2500.25};
    l.normal_azimuth_deg = 10.0f;
    l.normal_elevation_deg = 70.0f;
    append_cigi_response(l, swap, d);
    const auto got = decode_cigi_responses(d);
    ASSERT_TRUE(got);
    ASSERT_EQ(got->size(), 3u);
    const auto& h2 = std::get<HatHotResponse>((*got)[0]);
    EXPECT_EQ(h2.id, 11);
    EXPECT_EQ(h2.hat_m, 123.25);
    EXPECT_EQ(h2.host_frame, 9u);
    const auto& x2 = std::get<HatHotResponse>((*got)[1]);
    EXPECT_TRUE(x2.extended);
    EXPECT_EQ(x2.hot_m, 2000.5);
    EXPECT_EQ(x2.normal_azimuth_deg, -45.0f);
    const auto& l2 = std::get<LosResponse>((*got)[2]);
    EXPECT_EQ(l2.range_m, 1234.5);
    EXPECT_EQ(l2.point, l.point);
    EXPECT_TRUE(l2.range_valid);
    EXPECT_FALSE(l2.visible);
  }
}

// Found by fuzz_cigi: a 2-byte packet at the end of an IG datagram was read
// past its end (its byte 4). Under ASan this read is an error.
TEST(WireCigiQueries, ShortPacketAtTheEndOfResponses) {
  const auto sof = encode_cigi_start_of_frame(1, 2, 3, kCigiModeOperate, false);
  std::vector<std::uint8_t> heap(sof.begin(), sof.end());
  heap.push_back(77);
  heap.push_back(2);
  const auto r = decode_cigi_responses(std::span<const std::uint8_t>(heap.data(), heap.size()));
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->empty());
}

TEST(WireCigiQueriesRandomized, MutatedDatagramsGiveOnlySaneRequests) {
  std::mt19937_64 rng(26);
  HatHotRequest h;
  h.point = {37, -118, 100};
  LosSegmentRequest s;
  LosVectorRequest v;
  v.max_range_m = 100;
  std::size_t accepted = 0, rejected = 0;
  for (int k = 0; k < 100000; ++k) {
    const bool swap = rng() & 1;
    Bytes d = encode_cigi_host_datagram(1, 1, {}, swap);
    d = cat(cat(cat(d, encode_cigi_hat_hot_request(h, swap)), encode_cigi_los_segment_request(s, swap)),
            encode_cigi_los_vector_request(v, swap));
    const int flips = 1 + int(rng() % 8);
    for (int f = 0; f < flips; ++f) d[rng() % d.size()] ^= std::uint8_t(1u << (rng() % 8));
    if (rng() % 4 == 0) d.resize(rng() % (d.size() + 20));
    const auto r = decode_cigi_requests(d);
    rejected += r.rejects.size();
    for (const auto& q : r.requests) {
      ++accepted;
      if (const auto* a = std::get_if<HatHotRequest>(&q)) {
        ASSERT_TRUE(std::isfinite(a->point.x) && std::isfinite(a->point.y) && std::isfinite(a->point.z));
        ASSERT_NE(int(a->type), 3);
      } else if (const auto* b = std::get_if<LosVectorRequest>(&q)) {
        ASSERT_TRUE(b->min_range_m >= 0 && b->max_range_m >= b->min_range_m && std::isfinite(b->max_range_m));
        ASSERT_LE(std::abs(b->elevation_deg), 90.0f);
      } else {
        const auto& c = std::get<LosSegmentRequest>(q);
        ASSERT_TRUE(std::isfinite(c.source.x) && std::isfinite(c.destination.z));
      }
    }
  }
  EXPECT_GT(accepted, 10000u);
  EXPECT_GT(rejected, 1000u);
}

}  // namespace
