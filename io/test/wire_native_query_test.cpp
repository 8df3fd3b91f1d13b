// Native host service datagrams ("IGQR" / "IGQA"): layout against
// hand-written bytes, round trips, every reject reason.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "io/wire/crc32.h"
#include "io/wire/native_query.h"

namespace {

using namespace ig::io::wire;

TEST(WireNativeQuery, LayoutLittleEndianWithCrc) {
  NativeQuery q;
  q.kind = NativeQueryKind::LosVector;
  q.geodetic = true;
  q.id = 0x01020304;
  q.a = {37.5, -118.25, 3000.0};
  q.b = {0.0, 1.0, -1.0};
  q.min_range_m = 10.0;
  q.max_range_m = 20000.0;
  const auto b = encode_native_query(q);
  ASSERT_EQ(b.size(), 96u);
  EXPECT_EQ((std::vector<std::uint8_t>(b.begin(), b.begin() + 12)),
            (std::vector<std::uint8_t>{'I', 'G', 'Q', 'R', 1, 0, 3, 1, 4, 3, 2, 1}));
  // 37.5 = 0x4042C00000000000, little-endian at 16.
  EXPECT_EQ((std::vector<std::uint8_t>(b.begin() + 16, b.begin() + 24)),
            (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0xC0, 0x42, 0x40}));
  const std::uint32_t crc = crc32(std::span<const std::uint8_t>(b.data(), 92));
  EXPECT_EQ(b[92], crc & 0xFF);
  EXPECT_EQ(b[95], crc >> 24);
  const auto r = decode_native_query(b);
  ASSERT_TRUE(r.query);
  EXPECT_EQ(r.query->id, q.id);
  EXPECT_EQ(r.query->kind, q.kind);
  EXPECT_TRUE(r.query->geodetic);
  EXPECT_EQ(r.query->a, q.a);
  EXPECT_EQ(r.query->b, q.b);
  EXPECT_EQ(r.query->min_range_m, 10.0);
  EXPECT_EQ(r.query->max_range_m, 20000.0);
  EXPECT_TRUE(is_native_query(b));
}

TEST(WireNativeQuery, AnswersRoundTrip) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1e4, 1e4);
  for (int k = 0; k < 1000; ++k) {
    NativeAnswer a;
    a.kind = NativeQueryKind(1 + k % 3);
    a.geodetic = k & 1;
    a.valid = k & 2;
    a.hit = k & 4;
    a.id = std::uint32_t(rng());
    a.ig_frame = std::uint32_t(rng());
    a.hot_or_range_m = u(rng);
    a.hat_m = u(rng);
    a.point = {u(rng), u(rng), u(rng)};
    a.normal = {u(rng), u(rng), u(rng)};
    const auto b = encode_native_answer(a);
    const auto back = decode_native_answer(b);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->kind, a.kind);
    EXPECT_EQ(back->geodetic, a.geodetic);
    EXPECT_EQ(back->valid, a.valid);
    EXPECT_EQ(back->hit, a.hit);
    EXPECT_EQ(back->id, a.id);
    EXPECT_EQ(back->ig_frame, a.ig_frame);
    EXPECT_EQ(back->hot_or_range_m, a.hot_or_range_m);
    EXPECT_EQ(back->point, a.point);
    EXPECT_EQ(back->normal, a.normal);
    auto bad = b;
    bad[40] ^= 1;
    EXPECT_FALSE(decode_native_answer(bad));
  }
}

TEST(WireNativeQuery, Rejects) {
  NativeQuery q;
  q.a = {100, 200, 300};
  auto reject = [](const std::vector<std::uint8_t>& d) { return decode_native_query(d).reject; };
  auto bytes = [](const std::array<std::uint8_t, kNativeQuerySize>& a) { return std::vector<std::uint8_t>(a.begin(), a.end()); };
  auto good = bytes(encode_native_query(q));
  EXPECT_FALSE(reject(good));
  auto shorter = good;
  shorter.pop_back();
  EXPECT_EQ(reject(shorter), NativeQueryReject::WrongSize);
  auto magic = good;
  magic[3] = 'X';
  EXPECT_EQ(reject(magic), NativeQueryReject::BadMagic);
  auto version = good;
  version[4] = 2;
  EXPECT_EQ(reject(version), NativeQueryReject::BadVersion);
  auto crc = good;
  crc[20] ^= 0x10;
  EXPECT_EQ(reject(crc), NativeQueryReject::BadCrc);
  NativeQuery k = q;
  k.kind = NativeQueryKind(7);
  EXPECT_EQ(reject(bytes(encode_native_query(k))), NativeQueryReject::BadKind);
  NativeQuery nan = q;
  nan.a.y = NAN;
  EXPECT_EQ(reject(bytes(encode_native_query(nan))), NativeQueryReject::NonFinite);
  NativeQuery lat = q;
  lat.geodetic = true;
  lat.a = {95.0, 0.0, 0.0};
  EXPECT_EQ(reject(bytes(encode_native_query(lat))), NativeQueryReject::OutOfRange);
  NativeQuery ranges = q;
  ranges.kind = NativeQueryKind::LosVector;
  ranges.b = {1, 0, 0};
  ranges.min_range_m = 5;
  ranges.max_range_m = 1;
  EXPECT_EQ(reject(bytes(encode_native_query(ranges))), NativeQueryReject::OutOfRange);
  ranges.max_range_m = INFINITY;  // an unbounded vector is fine
  EXPECT_FALSE(reject(bytes(encode_native_query(ranges))));
}

}  // namespace
