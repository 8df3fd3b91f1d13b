// The entity table: states, attach to parents (and loops), clamp to a
// surface, dead reckoning from Rate Control, articulated parts, alpha and
// the entity cap. A flat-plane georeference (1 deg = 100 km) and a tilted
// plane stand in for the terrain.

#include <gtest/gtest.h>

#include <cmath>

#include "io/entities/entity_table.h"

namespace ig::io {
namespace {

using wire::CigiClamp;
using wire::CigiEntityControl;
using wire::CigiEntityState;

// lat, lon -> y, x at 100 km a degree; altitude -> z.
std::optional<glm::dvec3> to_local(double lat, double lon, double alt) { return glm::dvec3(lon * 1e5, lat * 1e5, alt); }
// A plane rising 1 m per 10 m eastwards from 100 m at x = 0.
std::optional<SurfaceSample> slope(double x, double) {
  return SurfaceSample{100.0 + 0.1 * x, glm::normalize(glm::dvec3(-0.1, 0.0, 1.0))};
}

CigiEntityControl entity(std::uint16_t id, glm::dvec3 lat_lon_alt, float yaw = 0.0f) {
  CigiEntityControl e;
  e.entity = id;
  e.type = 1;
  e.position = lat_lon_alt;
  e.yaw_deg = yaw;
  return e;
}
wire::CigiEntityPackets packets(std::initializer_list<CigiEntityControl> controls) {
  wire::CigiEntityPackets p;
  p.controls = controls;
  return p;
}

struct Table {
  EntityTable table{to_local, slope};
  Pose ownship{{0.0, 0.0, 500.0}, attitude_from_hpr({90.0, 0.0, 0.0})};
  void take(std::initializer_list<CigiEntityControl> c, double t = 0.0) { table.take(packets(c), {}, t); }
  std::optional<EntityPose> at(std::uint16_t id, double t = 0.0) const { return table.pose_of(id, t, ownship); }
};

TEST(EntityTable, StatesHideKeepAndRemove) {
  Table t;
  t.take({entity(2, {0.01, 0.02, 300.0}), entity(0, {0, 0, 0})});  // entity 0 is the ownship's: skipped
  ASSERT_TRUE(t.at(2));
  EXPECT_EQ(t.table.size(), 1u);
  EXPECT_NEAR(t.at(2)->pose.position.x, 2000.0, 1e-9);
  EXPECT_NEAR(t.at(2)->pose.position.y, 1000.0, 1e-9);
  auto hidden = entity(2, {0.01, 0.02, 300.0});
  hidden.state = CigiEntityState::Inactive;
  t.take({hidden});
  EXPECT_FALSE(t.at(2));
  EXPECT_EQ(t.table.size(), 1u);  // kept
  EXPECT_TRUE(t.table.poses_at(0.0, t.ownship).empty());
  auto gone = entity(2, {});
  gone.state = CigiEntityState::Destroyed;
  t.take({gone});
  EXPECT_EQ(t.table.size(), 0u);
}

TEST(EntityTable, ClampsToTheSurface) {
  Table t;
  auto flat = entity(3, {0.0, 0.005, 2.5}, 90.0f);  // x = 500 m: surface 150 m
  flat.clamp = CigiClamp::NonConformal;
  flat.pitch_deg = 5.0f;
  auto conformal = flat;
  conformal.entity = 4;
  conformal.clamp = CigiClamp::Conformal;
  t.take({flat, conformal});
  const auto a = t.at(3), b = t.at(4);
  ASSERT_TRUE(a && b);
  EXPECT_NEAR(a->pose.position.z, 152.5, 1e-9);
  EXPECT_NEAR(hpr_from_attitude(a->pose.attitude).pitch_deg, 5.0, 1e-6);  // non-conformal keeps the host's attitude
  EXPECT_NEAR(b->pose.position.z, 152.5, 1e-9);
  // Conformal: up is the surface normal; heading east, so the nose rises with the slope.
  const glm::dvec3 up = up_of(b->pose.attitude), n = glm::normalize(glm::dvec3(-0.1, 0.0, 1.0));
  EXPECT_NEAR(glm::dot(up, n), 1.0, 1e-9);
  EXPECT_NEAR(hpr_from_attitude(b->pose.attitude).pitch_deg, glm::degrees(std::atan(0.1)), 1e-6);
  EXPECT_NEAR(hpr_from_attitude(b->pose.attitude).heading_deg, 90.0, 1e-6);
}

TEST(EntityTable, AChildMovesWithItsParent) {
  Table t;
  auto child = entity(6, {10.0, 0.0, 0.0});  // 10 m ahead of its parent
  child.attached = true;
  child.parent = 5;
  child.inherit_alpha = true;
  auto parent = entity(5, {0.0, 0.0, 1000.0}, 0.0f);
  parent.alpha = 51;
  t.take({parent, child});
  auto c = t.at(6);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->parent, 5);
  EXPECT_NEAR(c->pose.position.y, 10.0, 1e-9);  // heading north: ahead is +y
  EXPECT_NEAR(c->pose.position.z, 1000.0, 1e-9);
  EXPECT_FLOAT_EQ(c->alpha, 51.0f / 255.0f);
  // The parent turns east and moves 1 km east: the child follows, still ahead.
  t.take({entity(5, {0.0, 0.01, 1000.0}, 90.0f)});
  c = t.at(6);
  EXPECT_NEAR(c->pose.position.x, 1010.0, 1e-6);
  EXPECT_NEAR(c->pose.position.y, 0.0, 1e-6);
  EXPECT_NEAR(hpr_from_attitude(c->pose.attitude).heading_deg, 90.0, 1e-6);
  // Attached to the ownship (heading east at 500 m): 20 m behind, 3 m below.
  auto wingman = entity(7, {-20.0, 0.0, 3.0});
  wingman.attached = true;
  wingman.parent = 0;
  t.take({wingman});
  EXPECT_NEAR(t.at(7)->pose.position.x, -20.0, 1e-9);
  EXPECT_NEAR(t.at(7)->pose.position.z, 497.0, 1e-9);
}

TEST(EntityTable, AttachLoopsAndMissingParentsAreReportedNotDrawn) {
  Table t;
  auto a = entity(10, {1, 0, 0}), b = entity(11, {1, 0, 0}), orphan = entity(12, {1, 0, 0});
  a.attached = b.attached = orphan.attached = true;
  a.parent = 11;
  b.parent = 10;
  orphan.parent = 99;
  t.take({a, b, orphan, entity(13, {0, 0, 0})});
  const auto drawn = t.table.poses_at(0.0, t.ownship);
  ASSERT_EQ(drawn.size(), 1u);
  EXPECT_EQ(drawn[0].id, 13);
  t.table.poses_at(0.0, t.ownship);  // again: no new messages
  const auto m = t.table.take_messages();
  ASSERT_EQ(m.size(), 3u);  // the loop seen from 10 and from 11, the orphan
  EXPECT_NE(m[0].find("attach loop"), std::string::npos) << m[0];
  EXPECT_NE(m[2].find("parent 99 does not exist"), std::string::npos) << m[2];
  EXPECT_TRUE(t.table.take_messages().empty());
}

TEST(EntityTable, RateControlDeadReckonsUntilStopped) {
  Table t;
  t.take({entity(20, {0.0, 0.0, 100.0}, 0.0f)}, 10.0);
  wire::CigiRateControl r;
  r.entity = 20;
  r.velocity_mps = {50.0, 10.0, -2.0};  // world: north, east, down
  r.rates_dps = {0.0, 0.0, 3.0};        // yaw 3 deg/s
  t.table.take({}, std::span(&r, 1), 10.0);
  auto p = t.at(20, 12.0);
  EXPECT_NEAR(p->pose.position.y, 100.0, 1e-9);
  EXPECT_NEAR(p->pose.position.x, 20.0, 1e-9);
  EXPECT_NEAR(p->pose.position.z, 104.0, 1e-9);
  EXPECT_NEAR(hpr_from_attitude(p->pose.attitude).heading_deg, 6.0, 1e-9);
  // Zero rates at t = 12: it stays where it got to.
  r.velocity_mps = r.rates_dps = glm::dvec3(0.0);
  t.table.take({}, std::span(&r, 1), 12.0);
  EXPECT_NEAR(t.at(20, 30.0)->pose.position.y, 100.0, 1e-9);
  // A new Entity Control replaces the place.
  t.take({entity(20, {0.0, 0.0, 100.0})}, 31.0);
  EXPECT_NEAR(t.at(20, 40.0)->pose.position.y, 0.0, 1e-9);
}

TEST(EntityTable, ArticulatedPartsMoveFromTheEntity) {
  Table t;
  t.take({entity(30, {0.0, 0.0, 50.0}, 0.0f)});
  wire::CigiEntityPackets p;
  wire::CigiArticulatedPart turret;
  turret.entity = 30;
  turret.part = 1;
  turret.yaw_deg = 45.0f;
  turret.z_m = -2.0f;  // 2 m up
  p.parts = {turret};
  wire::CigiArticulatedPart stray;
  stray.entity = 31;  // no such entity
  p.parts.push_back(stray);
  t.table.take(p, {}, 0.0);
  const auto part = t.table.part_pose_of(30, 1, 0.0, t.ownship);
  ASSERT_TRUE(part);
  EXPECT_NEAR(part->position.z, 52.0, 1e-9);
  EXPECT_NEAR(hpr_from_attitude(part->attitude).heading_deg, 45.0, 1e-9);
  ASSERT_EQ(t.at(30)->parts->count(1), 1u);
  EXPECT_EQ(t.table.summary()["parts-for-unknown-entity"], 1);
  wire::CigiEntityPackets bad;
  bad.rejects = {wire::QueryReject::NonFinite, wire::QueryReject::NonFinite, wire::QueryReject::WrongSize};
  t.table.take(bad, {}, 0.0);
  EXPECT_EQ(t.table.summary()["rejected-non-finite"], 2);
  EXPECT_EQ(t.table.summary()["rejected-wrong-size"], 1);
}

TEST(EntityTable, TheCapRefusesMoreEntitiesOnce) {
  EntityTable table(to_local, slope, EntityLimits{3, 4});
  wire::CigiEntityPackets p;
  for (std::uint16_t id = 1; id <= 5; ++id) p.controls.push_back(entity(id, {0, 0, 0}));
  table.take(p, {}, 0.0);
  EXPECT_EQ(table.size(), 3u);
  EXPECT_EQ(table.summary()["too-many-entities"], 2);
  EXPECT_EQ(table.take_messages().size(), 2u);  // one per refused id
}

}  // namespace
}  // namespace ig::io
