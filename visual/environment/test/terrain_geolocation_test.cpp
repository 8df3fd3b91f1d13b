// Where a terrain-local point is on the Earth and which way true north is
// (environment/terrain_geolocation.h), on a geographic grid and a UTM grid.
#include "environment/terrain_geolocation.h"

#include <ogr_spatialref.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "terrain/dem_loader.h"
#include "terrain/georef.h"

namespace {

using ig::environment::TerrainGeolocation;
constexpr double kRad = 0.017453292519943295;

ig::terrain::Heightfield flat(int n, double spacing_m) {
  ig::terrain::Heightfield hf;
  hf.width = hf.height = n;
  hf.spacing_x_m = hf.spacing_y_m = spacing_m;
  hf.heights.assign(std::size_t(n) * n, 0.0f);
  return hf;
}

// A UTM zone 11N grid (central meridian 117 W) whose south-west sample is at
// (easting, northing).
ig::terrain::Heightfield utm_grid(double easting, double northing) {
  auto hf = flat(101, 30.0);
  OGRSpatialReference utm;
  utm.importFromEPSG(32611);
  char* wkt = nullptr;
  utm.exportToWkt(&wkt);
  hf.georef = ig::terrain::GeoReference{wkt, "EPSG:32611", false, {easting, 30.0, 0.0, northing, 0.0, 30.0}};
  CPLFree(wkt);
  return hf;
}

TEST(TerrainGeolocation, NoGeoreferenceNoPlace) {
  EXPECT_EQ(TerrainGeolocation::make(flat(17, 30.0)), nullptr);
}

TEST(TerrainGeolocation, GeographicGridNorthIsTrueNorth) {
  auto hf = flat(101, 30.0);
  hf.georef = ig::terrain::make_geographic_georef(46.5, 7.9, 30.0, 30.0);
  const auto geo = TerrainGeolocation::make(hf);
  ASSERT_NE(geo, nullptr);
  const auto m = ig::terrain::metres_per_angle(46.5);
  const auto p = geo->locate({2000.0, 1000.0});
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(p->latitude_deg, 46.5 + 1000.0 / m.north, 1e-9);
  EXPECT_NEAR(p->longitude_deg, 7.9 + 2000.0 / m.east, 1e-9);
  EXPECT_NEAR(p->grid_north_deg, 0.0, 1e-9);
}

TEST(TerrainGeolocation, UtmGridNorthTurnsByTheMeridianConvergence) {
  // West of the central meridian in the northern hemisphere grid north lies
  // west of true north, by about atan(tan(lon - lon0) sin(lat)).
  for (const double lon : {-120.0, -117.0, -115.0}) {
    SCOPED_TRACE(lon);
    const double lat = 37.0;
    // Place the grid so that the point sits inside it.
    OGRSpatialReference wgs84, utm;
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    utm.importFromEPSG(32611);
    utm.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&wgs84, &utm));
    ASSERT_TRUE(ct);
    double x = lon, y = lat;
    ASSERT_TRUE(ct->Transform(1, &x, &y));
    const auto hf = utm_grid(x - 1500.0, y - 1500.0);
    const auto geo = TerrainGeolocation::make(hf);
    ASSERT_NE(geo, nullptr);
    const auto local = ig::terrain::geodetic_to_local(hf, lat, lon);
    ASSERT_TRUE(local.has_value());
    const auto p = geo->locate(*local);
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->latitude_deg, lat, 1e-7);
    EXPECT_NEAR(p->longitude_deg, lon, 1e-7);
    const double expected = std::atan(std::tan((lon + 117.0) * kRad) * std::sin(lat * kRad)) / kRad;
    EXPECT_NEAR(p->grid_north_deg, expected, 0.01);
  }
}

TEST(TerrainGeolocation, DirectionsTurnWithGridNorth) {
  using ig::environment::angles_of;
  using ig::environment::local_direction;
  // The sun due true south, 30 deg up, where grid north is 2 deg east of
  // true north: in grid axes it sits 2 deg west of grid south.
  const glm::dvec3 d = local_direction(180.0, 30.0, 2.0);
  EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
  EXPECT_NEAR(std::atan2(d.x, d.y) / kRad, 178.0, 1e-9);
  const auto back = angles_of(d * 3.0, 2.0);
  EXPECT_NEAR(back.elevation_deg, 30.0, 1e-9);
  EXPECT_NEAR(back.azimuth_deg, 180.0, 1e-9);
  // Azimuths stay in [0, 360).
  EXPECT_NEAR(angles_of(local_direction(359.5, 10.0, 0.0), 0.0).azimuth_deg, 359.5, 1e-9);
  EXPECT_NEAR(angles_of(local_direction(0.5, 10.0, 1.0), 1.0).azimuth_deg, 0.5, 1e-9);
  EXPECT_NEAR(angles_of({0.0, 0.0, 1.0}, 0.0).elevation_deg, 90.0, 1e-12);
}

}  // namespace
