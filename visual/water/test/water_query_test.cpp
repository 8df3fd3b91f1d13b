// Host queries over water (terrain/terrain_query.h): the height of a point
// on water is the water's level, its material Water; a line stops at the
// water's surface, also where the ground under it lies deeper, also with
// the Earth's curvature; land stays land.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "terrain/earth_curvature.h"
#include "terrain/terrain_query.h"
#include "water/test/water_test_terrain.h"
#include "water/water_detection.h"

namespace ig::water {
namespace {

using terrain::SurfaceMaterial;
using terrain::TerrainQuery;
using test::kLakeLevel;
using test::TestFeatures;

struct WaterTerrain {
  TestFeatures f;
  terrain::Heightfield hf = test::make_water_test_terrain(200, 150, f);
  WaterTerrain() { hf.water = std::make_shared<WaterMap>(detect_water(hf)); }
  glm::dvec2 at(double i, double j) const { return {i * hf.spacing_x_m, j * hf.spacing_y_m}; }
};

TEST(WaterQuery, HeightOverWaterIsTheWatersLevel) {
  const WaterTerrain t;
  const TerrainQuery q(t.hf, 0.0);
  const glm::dvec2 lake = t.at(t.f.lake_i + 0.3, t.f.lake_j - 0.6);
  const auto s = q.surface_at(lake.x, lake.y);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->material, SurfaceMaterial::Water);
  EXPECT_EQ(s->height_m, kLakeLevel);
  EXPECT_EQ(s->normal, glm::dvec3(0.0, 0.0, 1.0));
  const glm::dvec2 sea = t.at(100.5, 3.2);
  EXPECT_EQ(q.surface_at(sea.x, sea.y)->material, SurfaceMaterial::Water);
  EXPECT_EQ(q.surface_at(sea.x, sea.y)->height_m, 0.0);
  // Land: the rough ground, and the playa and terraces that are not water.
  for (const glm::dvec2 p : {t.at(150.5, 100.5), t.at(t.f.playa_i, t.f.playa_j), t.at(100.0, 30.0)}) {
    const auto l = q.surface_at(p.x, p.y);
    ASSERT_TRUE(l);
    EXPECT_EQ(l->material, SurfaceMaterial::Land);
    EXPECT_DOUBLE_EQ(l->height_m, t.hf.sample_surface(p.x, p.y));
  }
}

TEST(WaterQuery, LinesStopAtTheWater) {
  const WaterTerrain t;
  const TerrainQuery q(t.hf, 0.0);
  const glm::dvec2 lake = t.at(t.f.lake_i, t.f.lake_j);
  // Straight down onto the lake: at its level, water.
  const auto down = q.segment({lake.x, lake.y, kLakeLevel + 300.0}, {lake.x, lake.y, kLakeLevel - 300.0});
  ASSERT_TRUE(down);
  EXPECT_EQ(down->material, SurfaceMaterial::Water);
  EXPECT_NEAR(down->range_m, 300.0, 1e-6);
  EXPECT_NEAR(down->point.z, kLakeLevel, 1e-6);
  // Down onto land: land.
  const glm::dvec2 land = t.at(150.5, 100.5);
  const auto dry = q.ray({land.x, land.y, 2000.0}, {0.0, 0.0, -1.0}, 0.0, 5000.0);
  ASSERT_TRUE(dry);
  EXPECT_EQ(dry->material, SurfaceMaterial::Land);
  EXPECT_NEAR(dry->point.z, t.hf.sample_surface(land.x, land.y), 1e-6);
}

TEST(WaterQuery, LinesStopAtTheSurfaceNotTheBedUnderIt) {
  // A map whose water was not made level (paged heights keep the file's):
  // the ground under the lake 20 m deep; the line stops at the surface.
  WaterTerrain t;
  for (int j = 0; j < t.hf.height; ++j)
    for (int i = 0; i < t.hf.width; ++i)
      if (t.hf.water->body_at(i, j) == std::optional<std::uint32_t>(1)) t.hf.ref(i, j) = kLakeLevel - 20.0f;
  const TerrainQuery q(t.hf, 0.0);
  const glm::dvec2 lake = t.at(t.f.lake_i, t.f.lake_j);
  const auto hit = q.ray({lake.x - 500.0, lake.y, kLakeLevel + 50.0}, {500.0, 0.0, -60.0}, 0.0, 1e4);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->material, SurfaceMaterial::Water);
  EXPECT_NEAR(hit->point.z, kLakeLevel, 1e-9);
  EXPECT_NEAR(hit->range_m, 50.0 / 60.0 * std::hypot(500.0, 60.0), 1e-6);
  // From under the surface, upwards: stops at it too.
  const auto up = q.ray({lake.x, lake.y, kLakeLevel - 10.0}, {0.0, 0.0, 1.0}, 0.0, 100.0);
  ASSERT_TRUE(up);
  EXPECT_EQ(up->material, SurfaceMaterial::Water);
  EXPECT_NEAR(up->range_m, 10.0, 1e-9);
}

TEST(WaterQuery, TheSeaCurvesAwayLikeTheTerrain) {
  // A line 10 m over the sea, dipping 3 m per km: on a flat Earth it meets
  // the sea at 3.33 km; the sea lowered by the drop t^2 / 2R (as drawn) it
  // meets later, where 10 - 0.003 t = -t^2 / 2R.
  const WaterTerrain t;
  const TerrainQuery flat(t.hf, 0.0), round(t.hf, terrain::kEarthRadiusM);
  const glm::dvec2 from = t.at(10.0, 5.0);
  const glm::dvec3 dir(1.0, 0.0, -0.003);
  const auto a = flat.ray({from.x, from.y, 10.0}, dir, 0.0, 2e4);
  const auto b = round.ray({from.x, from.y, 10.0}, dir, 0.0, 2e4);
  ASSERT_TRUE(a);
  ASSERT_TRUE(b);
  EXPECT_EQ(a->material, SurfaceMaterial::Water);
  EXPECT_EQ(b->material, SurfaceMaterial::Water);
  const double n = std::hypot(1.0, 0.003);
  EXPECT_NEAR(a->range_m, 10.0 / 0.003 * n, 1e-6);
  const double k = 1.0 / (2.0 * terrain::kEarthRadiusM);  // k t^2 - 0.003 t + 10 = 0, the nearer root
  const double along = (0.003 - std::sqrt(9e-6 - 40.0 * k)) / (2.0 * k);
  EXPECT_NEAR(b->range_m, along * n, 1.0);
  EXPECT_GT(b->range_m, a->range_m + 300.0);
  // Dipping 1 m per km it passes over the horizon (1.8 mrad down from 10 m): no hit.
  EXPECT_FALSE(round.ray({from.x, from.y, 10.0}, {1.0, 0.0, -0.001}, 0.0, 1.5e4));
}

}  // namespace
}  // namespace ig::water
