// The shared CIGI request load (tools/load/cigi_request_mix.h): what the
// benchmark and the loopback host send, decoded back.
#include <variant>

#include <gtest/gtest.h>

#include "io/wire/cigi_queries.h"
#include "load/cigi_request_mix.h"
#include "terrain/test/ramp_terrain.h"

namespace {

using namespace ig::io::wire;
using ig::load::CigiRequestMix;
using ig::load::RequestLoad;

using ig::terrain::test::make_ramp_terrain;

TEST(CigiRequestMix, MixOfRequestTypesInAlternatingByteOrder) {
  const auto hf = make_ramp_terrain();
  CigiRequestMix mix(hf);
  const RequestLoad load{30, 10, 0.0};
  for (std::uint32_t frame = 1; frame <= 2; ++frame) {
    const auto d = mix.datagram(frame, load, {});
    const CigiRequests got = decode_cigi_requests(d);
    ASSERT_EQ(got.host_frame, frame);
    EXPECT_EQ(got.byte_swapped, frame % 2 == 1);
    EXPECT_TRUE(got.rejects.empty());
    ASSERT_EQ(got.requests.size(), 40u);
    int hat_hot[3] = {0, 0, 0}, segments = 0, vectors = 0;
    for (std::size_t k = 0; k < got.requests.size(); ++k) {
      const CigiRequest& r = got.requests[k];
      if (const auto* h = std::get_if<HatHotRequest>(&r)) {
        ASSERT_LT(k, 30u);
        EXPECT_EQ(h->id, k);
        ++hat_hot[int(h->type)];
        EXPECT_NEAR(h->point.z, 3000.0, 1e-6);
      } else if (const auto* s = std::get_if<LosSegmentRequest>(&r)) {
        EXPECT_TRUE(s->extended);
        EXPECT_EQ(s->id % 2, 0);
        ++segments;
      } else if (const auto* v = std::get_if<LosVectorRequest>(&r)) {
        EXPECT_TRUE(v->extended);
        EXPECT_EQ(v->id % 2, 1);
        EXPECT_LE(v->elevation_deg, -5.0f);
        EXPECT_GE(v->elevation_deg, -30.0f);
        ++vectors;
      }
    }
    EXPECT_EQ(hat_hot[0], 10);
    EXPECT_EQ(hat_hot[1], 10);
    EXPECT_EQ(hat_hot[2], 10);
    EXPECT_EQ(segments, 5);
    EXPECT_EQ(vectors, 5);
  }
}

TEST(CigiRequestMix, SameSeedSameLoad) {
  const auto hf = make_ramp_terrain();
  CigiRequestMix a(hf), b(hf), c(hf, 16);
  const RequestLoad load{12, 6, 500.0};
  for (std::uint32_t frame = 1; frame <= 3; ++frame) {
    const auto da = a.datagram(frame, load, {});
    EXPECT_EQ(da, b.datagram(frame, load, {}));
    EXPECT_NE(da, c.datagram(frame, load, {}));
  }
}

TEST(CigiRequestMix, SpreadKeepsPointsNearTheOwnship) {
  const auto hf = make_ramp_terrain();
  CigiRequestMix mix(hf);
  const auto own = mix.geodetic(mix.ownship_at());
  const auto far = mix.geodetic(mix.ownship_at() + glm::dvec3(200.0, 200.0, 0.0));
  const auto got = decode_cigi_requests(mix.datagram(2, RequestLoad{50, 0, 100.0}, {}));
  ASSERT_EQ(got.requests.size(), 50u);
  for (const CigiRequest& r : got.requests) {
    const auto& p = std::get<HatHotRequest>(r).point;
    EXPECT_LT(std::abs(p.x - own.x), std::abs(far.x - own.x));
    EXPECT_LT(std::abs(p.y - own.y), std::abs(far.y - own.y));
  }
}

TEST(CigiRequestMix, AroundAMovingOwnshipKeepsPointsAndLineSourcesNearIt) {
  const auto hf = make_ramp_terrain();
  CigiRequestMix mix(hf);
  const glm::dvec3 at(0.25 * hf.extent_x_m(), 0.7 * hf.extent_y_m(), 0.0);
  const auto own = mix.geodetic(at);
  const auto far = mix.geodetic(at + glm::dvec3(200.0, 200.0, 0.0));
  auto near = [&](const glm::dvec3& p) {
    EXPECT_LT(std::abs(p.x - own.x), std::abs(far.x - own.x));
    EXPECT_LT(std::abs(p.y - own.y), std::abs(far.y - own.y));
  };
  const auto got = decode_cigi_requests(mix.datagram(2, RequestLoad{30, 10, 100.0, 100.0}, {}, at));
  ASSERT_EQ(got.requests.size(), 40u);
  for (const CigiRequest& r : got.requests) {
    if (const auto* h = std::get_if<HatHotRequest>(&r)) near(h->point);
    else if (const auto* s = std::get_if<LosSegmentRequest>(&r)) near(s->source);
    else near(std::get<LosVectorRequest>(r).source);
  }
  // Near a corner every point stays on the DEM.
  const auto corner = decode_cigi_requests(mix.datagram(3, RequestLoad{30, 0, 500.0}, {}, glm::dvec3(0.0)));
  const auto sw = mix.geodetic(glm::dvec3(0.0));
  for (const CigiRequest& r : corner.requests) {
    const auto& p = std::get<HatHotRequest>(r).point;
    EXPECT_GE(p.x, sw.x - 1e-9);
    EXPECT_GE(p.y, sw.y - 1e-9);
  }
}

TEST(CigiRequestMix, NeedsAGeographicDem) {
  const auto hf = make_ramp_terrain(false);
  EXPECT_THROW(CigiRequestMix{hf}, std::runtime_error);
}

}  // namespace
