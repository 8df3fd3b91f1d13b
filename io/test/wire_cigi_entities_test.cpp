// CIGI 3.3 Entity Control for any entity and Articulated Part Control:
// hand-written big-endian bytes (offsets from the ICD) against the decoder,
// round trips in both orders, every reject; and one datagram of every
// packet family decoded once into its groups.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>
#include <utility>
#include <vector>

#include "io/wire/cigi.h"
#include "io/wire/cigi_entities.h"
#include "io/wire/cigi_host_datagram.h"

namespace {

using namespace ig::io::wire;
using Bytes = std::vector<std::uint8_t>;

// An IG Control (host frame 9) in this machine's order or swapped.
Bytes ig_control(bool swap) {
  PoseMessage none;
  Bytes d = encode_cigi_host_datagram(9, kCigiModeOperate, none, swap);
  d.resize(kCigiIgControlSize);
  return d;
}
template <class... Packets>
Bytes datagram(bool swap, const Packets&... packets) {
  Bytes d = ig_control(swap);
  (d.insert(d.end(), packets.begin(), packets.end()), ...);
  return d;
}
void put_be(Bytes& b, std::size_t at, std::uint64_t v, int n) {
  for (int k = 0; k < n; ++k) b[at + std::size_t(n - 1 - k)] = std::uint8_t(v >> (8 * k));
}

CigiEntityControl tanker() {
  CigiEntityControl e;
  e.entity = 2;
  e.state = CigiEntityState::Active;
  e.clamp = CigiClamp::NonConformal;
  e.collision_detection = true;
  e.alpha = 200;
  e.type = 2;
  e.roll_deg = 1.5f;
  e.pitch_deg = -2.25f;
  e.yaw_deg = 271.0f;
  e.position = {35.25, 138.75, 0.0};
  return e;
}

TEST(CigiEntities, HandWrittenEntityControlDecodes) {
  // Big-endian bytes at the ICD's offsets: entity 513, state destroyed (2),
  // attached, inherit alpha, conformal clamp (2 << 5), alpha 17, type 3,
  // parent 4, yaw 90, offsets x 10, y -5, z -2.5.
  Bytes p(48, 0);
  p[0] = 2;
  p[1] = 48;
  put_be(p, 2, 513, 2);
  p[4] = std::uint8_t(2 | (1u << 2) | (1u << 4) | (2u << 5));
  p[6] = 17;
  put_be(p, 8, 3, 2);
  put_be(p, 10, 4, 2);
  put_be(p, 20, std::bit_cast<std::uint32_t>(90.0f), 4);
  put_be(p, 24, std::bit_cast<std::uint64_t>(10.0), 8);
  put_be(p, 32, std::bit_cast<std::uint64_t>(-5.0), 8);
  put_be(p, 40, std::bit_cast<std::uint64_t>(-2.5), 8);
  const bool swap = std::endian::native == std::endian::little;  // big-endian on this machine means swapped
  const auto d = decode_cigi(datagram(swap, p));
  ASSERT_EQ(d.entities.controls.size(), 1u);
  const auto& e = d.entities.controls[0];
  EXPECT_EQ(e.entity, 513);
  EXPECT_EQ(e.state, CigiEntityState::Destroyed);
  EXPECT_TRUE(e.attached);
  EXPECT_TRUE(e.inherit_alpha);
  EXPECT_FALSE(e.collision_detection);
  EXPECT_EQ(e.clamp, CigiClamp::Conformal);
  EXPECT_EQ(e.alpha, 17);
  EXPECT_EQ(e.type, 3);
  EXPECT_EQ(e.parent, 4);
  EXPECT_EQ(e.yaw_deg, 90.0f);
  EXPECT_EQ(e.position, glm::dvec3(10.0, -5.0, -2.5));
  EXPECT_EQ(d.ownship.reject, Reject::NoPose);  // no entity 0 in it
}

TEST(CigiEntities, RoundTripBothOrders) {
  for (bool swap : {false, true}) {
    CigiArticulatedPart part;
    part.entity = 2;
    part.part = 7;
    part.yaw_deg = 45.0f;
    part.z_m = -0.5f;
    CigiArticulatedPart hidden;
    hidden.entity = 3;
    hidden.enabled = false;
    const auto d = decode_cigi(datagram(swap, encode_cigi_entity_control(tanker(), swap),
                                        encode_cigi_articulated_part(part, swap),
                                        encode_cigi_articulated_part(hidden, swap)));
    ASSERT_EQ(d.entities.controls.size(), 1u) << swap;
    EXPECT_EQ(d.entities.controls[0], tanker());
    ASSERT_EQ(d.entities.parts.size(), 2u);
    EXPECT_EQ(d.entities.parts[0], part);
    EXPECT_EQ(d.entities.parts[1], hidden);
    EXPECT_TRUE(d.entities.rejects.empty());
    EXPECT_TRUE(d.host.unsupported.empty());  // Articulated Part Control is taken
  }
}

TEST(CigiEntities, EveryRejectReason) {
  auto reject_of = [](const Bytes& packet) {
    const auto d = decode_cigi(datagram(false, packet));
    EXPECT_TRUE(d.entities.controls.empty() && d.entities.parts.empty());
    return d.entities.rejects.size() == 1 ? d.entities.rejects[0] : QueryReject::BadType;
  };
  auto entity = [](auto change) {
    CigiEntityControl e = tanker();
    change(e);
    const auto a = encode_cigi_entity_control(e, false);
    return Bytes(a.begin(), a.end());
  };
  EXPECT_EQ(reject_of(entity([](auto& e) { e.yaw_deg = NAN; })), QueryReject::NonFinite);
  EXPECT_EQ(reject_of(entity([](auto& e) { e.position.z = INFINITY; })), QueryReject::NonFinite);
  EXPECT_EQ(reject_of(entity([](auto& e) { e.position.x = 91.0; })), QueryReject::OutOfRange);
  EXPECT_EQ(reject_of(entity([](auto& e) { e.position.y = 360.0; })), QueryReject::OutOfRange);
  EXPECT_EQ(reject_of(entity([](auto& e) {
              e.attached = true;
              e.position = {2e7, 0, 0};
            })),
            QueryReject::OutOfRange);
  Bytes state3 = entity([](auto&) {});
  state3[4] |= 3;
  EXPECT_EQ(reject_of(state3), QueryReject::OutOfRange);
  Bytes clamp3 = entity([](auto&) {});
  clamp3[4] |= 3u << 5;
  EXPECT_EQ(reject_of(clamp3), QueryReject::OutOfRange);
  Bytes short_control = entity([](auto&) {});
  short_control.resize(40);
  short_control[1] = 40;
  EXPECT_EQ(reject_of(short_control), QueryReject::WrongSize);

  CigiArticulatedPart part;
  part.roll_deg = NAN;
  const auto nan_part = encode_cigi_articulated_part(part, false);
  EXPECT_EQ(reject_of(Bytes(nan_part.begin(), nan_part.end())), QueryReject::NonFinite);
  part.roll_deg.reset();
  part.x_m = 2e4f;
  const auto far_part = encode_cigi_articulated_part(part, false);
  EXPECT_EQ(reject_of(Bytes(far_part.begin(), far_part.end())), QueryReject::OutOfRange);
  Bytes cut(far_part.begin(), far_part.begin() + 16);  // the size byte says 32: past the end
  EXPECT_EQ(reject_of(cut), QueryReject::Truncated);
}

// One datagram with a packet of every family: each lands in its group, the
// ownship pose comes from entity 0, and the other entities are all there.
TEST(CigiHostDatagram, EveryFamilyDecodedOnceIntoItsGroup) {
  PoseMessage own;
  own.frame = PoseMessage::Frame::Geodetic;
  own.position = {35.0, 138.5, 1200.0};
  own.heading_deg = 30.0;
  Bytes d = encode_cigi_host_datagram(11, kCigiModeOperate, own, false);
  auto add = [&](const auto& packet) { d.insert(d.end(), packet.begin(), packet.end()); };
  add(encode_cigi_entity_control(tanker(), false));
  HatHotRequest hot;
  hot.id = 5;
  hot.point = {35.1, 138.6, 0.0};
  add(encode_cigi_hat_hot_request(hot, false));
  CigiViewControl view;
  view.view = 0;
  view.entity = 2;
  add(encode_cigi_view_control(view, false));
  CigiPositionRequest where;
  where.of.object = 2;
  add(encode_cigi_position_request(where, false));
  CigiArticulatedPart part;
  part.entity = 2;
  add(encode_cigi_articulated_part(part, false));
  const Bytes unknown = {200, 8, 0, 0, 0, 0, 0, 0};
  add(unknown);

  const CigiHostDatagram g = decode_cigi(d);
  ASSERT_TRUE(g.framed());
  ASSERT_TRUE(g.ownship.pose);
  EXPECT_DOUBLE_EQ(g.ownship.pose->position.x, 35.0);
  EXPECT_EQ(g.ownship.host_frame, 11u);
  ASSERT_EQ(g.entities.controls.size(), 2u);  // the ownship's and entity 2's
  EXPECT_EQ(g.entities.controls[0].entity, 0);
  EXPECT_EQ(g.entities.controls[1], tanker());
  EXPECT_EQ(g.entities.parts.size(), 1u);
  ASSERT_EQ(g.requests.requests.size(), 1u);
  EXPECT_EQ(request_id(g.requests.requests[0]), 5);
  EXPECT_EQ(g.requests.host_frame, 11u);
  ASSERT_EQ(g.views.controls.size(), 1u);
  EXPECT_EQ(g.views.controls[0].entity, 2);
  ASSERT_EQ(g.host.positions.size(), 1u);
  EXPECT_EQ(g.host.positions[0].of.object, 2);
  EXPECT_EQ(g.host.unsupported, std::vector<std::uint8_t>{200});
  // The per-family decoders read the same groups.
  EXPECT_EQ(decode_cigi_requests(d).requests.size(), 1u);
  EXPECT_EQ(decode_cigi_host_packets(d).positions.size(), 1u);
  EXPECT_EQ(decode_cigi_view_packets(d).controls.size(), 1u);
  EXPECT_TRUE(decode_cigi_host_datagram(d).pose);

  // A refused framing fills no group.
  Bytes bad = d;
  bad[2] = 2;  // CIGI 2
  const CigiHostDatagram r = decode_cigi(bad);
  EXPECT_FALSE(r.framed());
  EXPECT_EQ(r.ownship.reject, Reject::BadVersion);
  EXPECT_TRUE(r.entities.controls.empty() && r.requests.requests.empty() && r.host.positions.empty());
}

}  // namespace
