// A scenario's scripted entities placed at a time: along their paths,
// clamped to the surface every frame, attached to a parent (or the
// ownship), the same places for the same time.
#include <gtest/gtest.h>

#include <cmath>

#include "io/scenario.h"
#include "session/scenario_entities.h"
#include "terrain/heightfield.h"

namespace {

using namespace ig;

// A plane rising 0.1 m per metre eastwards, 1 m samples.
terrain::Heightfield slope() {
  terrain::Heightfield hf;
  hf.width = hf.height = 201;
  hf.spacing_x_m = hf.spacing_y_m = 1.0;
  hf.heights.resize(std::size_t(hf.width) * hf.height);
  for (int j = 0; j < hf.height; ++j)
    for (int i = 0; i < hf.width; ++i) hf.heights[std::size_t(j) * hf.width + i] = float(0.1 * i);
  hf.finalize_stats();
  return hf;
}

io::EntitySpec entity(std::uint16_t id, std::vector<io::PathKey> keys) {
  io::EntitySpec e;
  e.id = id;
  e.type = 1;
  e.path.keys = std::move(keys);
  return e;
}

TEST(ScenarioEntities, PathsClampsAndParents) {
  const auto hf = slope();
  auto truck = entity(1, {{0.0, {20, 50, 1.5}, 90, 0, 0}, {10.0, {120, 50, 1.5}, 90, 0, 0}});
  truck.clamp = io::EntityClamp::Conformal;
  auto trailer = entity(2, {{0.0, {0, -8, 0}, 0, 0, 0}});  // 8 m behind the truck
  trailer.parent = 1;
  auto wingman = entity(3, {{0.0, {15, -10, 0}, 0, 0, 0}});  // right of and behind the ownship
  wingman.parent = 0;
  session::ScenarioEntities s({truck, trailer, wingman}, hf);
  const io::Pose ownship{{100, 100, 500}, io::attitude_from_hpr({0, 0, 0})};
  const auto at5 = s.at(5.0, ownship);
  ASSERT_EQ(at5.size(), 3u);
  // Halfway along: x 70, on the surface (7 m) plus 1.5 m, nose up with the slope.
  EXPECT_NEAR(at5[0].position.x, 70.0, 1e-9);
  EXPECT_NEAR(at5[0].position.z, 7.0 + 1.5, 1e-6);
  EXPECT_NEAR(io::hpr_from_attitude(at5[0].attitude).pitch_deg, glm::degrees(std::atan(0.1)), 1e-4);  // float heights
  // The trailer: 8 m behind along the truck's (sloped) axis.
  EXPECT_NEAR(glm::length(at5[1].position - at5[0].position), 8.0, 1e-9);
  EXPECT_LT(at5[1].position.x, at5[0].position.x);
  EXPECT_NEAR(at5[2].position.x, 115.0, 1e-9);
  EXPECT_NEAR(at5[2].position.y, 90.0, 1e-9);
  // Deterministic: the same time, the same places.
  const auto again = s.at(5.0, ownship);
  for (std::size_t k = 0; k < at5.size(); ++k) EXPECT_EQ(at5[k].position, again[k].position);
}

}  // namespace
