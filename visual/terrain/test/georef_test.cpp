// Geodetic placement on georeferenced grids (terrain/georef.h).
#include <gtest/gtest.h>

#include <cmath>

#include "terrain/dem_loader.h"
#include "terrain/georef.h"

#include <ogr_spatialref.h>

namespace {

ig::terrain::Heightfield grid_with_origin(double lat0, double lon0) {
  ig::terrain::Heightfield hf;
  hf.width = hf.height = 101;
  hf.spacing_x_m = hf.spacing_y_m = 30.0;
  hf.heights.assign(101 * 101, 0.0f);
  hf.georef = ig::terrain::make_geographic_georef(lat0, lon0, 30.0, 30.0);
  return hf;
}

TEST(Georef, OriginMapsToTheSouthWestSample) {
  const auto hf = grid_with_origin(46.5, 7.9);
  const auto p = ig::terrain::geodetic_to_local(hf, 46.5, 7.9);
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(p->x, 0.0, 1e-6);
  EXPECT_NEAR(p->y, 0.0, 1e-6);
}

TEST(Georef, OneKilometreNorthAndEast) {
  const auto hf = grid_with_origin(46.5, 7.9);
  const auto m = ig::terrain::metres_per_angle(46.5);
  const auto p = ig::terrain::geodetic_to_local(hf, 46.5 + 1000.0 / m.north, 7.9 + 1000.0 / m.east);
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(p->x, 1000.0, 1e-6);
  EXPECT_NEAR(p->y, 1000.0, 1e-6);
}

TEST(Georef, NoGeoreferenceMeansNoPlacement) {
  auto hf = grid_with_origin(46.5, 7.9);
  hf.georef.reset();
  EXPECT_FALSE(ig::terrain::geodetic_to_local(hf, 46.5, 7.9).has_value());
}

TEST(Georef, NonFiniteInputIsRejected) {
  const auto hf = grid_with_origin(46.5, 7.9);
  EXPECT_FALSE(ig::terrain::geodetic_to_local(hf, std::nan(""), 7.9).has_value());
}

TEST(Georef, LocalToGeodeticInvertsThePlacement) {
  const auto hf = grid_with_origin(46.5, 7.9);
  const auto g = ig::terrain::local_to_geodetic(hf, 1234.0, 2345.0);
  ASSERT_TRUE(g.has_value());
  const auto back = ig::terrain::geodetic_to_local(hf, g->x, g->y);
  ASSERT_TRUE(back.has_value());
  EXPECT_NEAR(back->x, 1234.0, 1e-6);
  EXPECT_NEAR(back->y, 2345.0, 1e-6);
  auto plain = hf;
  plain.georef.reset();
  EXPECT_FALSE(ig::terrain::local_to_geodetic(plain, 0.0, 0.0).has_value());
}

// A projected DEM (UTM zone 11N, 30 m cells, south-west sample at
// 400000 E, 4000000 N): local metres are the easting / northing offsets.
TEST(Georef, LocalToGeodeticOnAProjectedGrid) {
  auto hf = grid_with_origin(46.5, 7.9);
  OGRSpatialReference utm;
  ASSERT_EQ(utm.importFromEPSG(32611), OGRERR_NONE);
  char* wkt = nullptr;
  utm.exportToWkt(&wkt);
  hf.georef->crs_wkt = wkt;
  CPLFree(wkt);
  hf.georef->geographic = false;
  hf.georef->grid_to_crs = {400000.0, 30.0, 0.0, 4000000.0, 0.0, 30.0};
  const auto g = ig::terrain::local_to_geodetic(hf, 300.0, 600.0);
  ASSERT_TRUE(g.has_value());
  // 400 300 E, 4 000 600 N in zone 11N (central meridian 117 W) lies near 36.14 N, 118.11 W.
  EXPECT_NEAR(g->x, 36.14, 0.02);
  EXPECT_NEAR(g->y, -118.11, 0.02);
  const auto back = ig::terrain::geodetic_to_local(hf, g->x, g->y);
  ASSERT_TRUE(back.has_value());
  EXPECT_NEAR(back->x, 300.0, 1e-3);
  EXPECT_NEAR(back->y, 600.0, 1e-3);
}

}  // namespace
