// WGS84 geodesy (io/filter/geodesy.h): known ECEF values, round trips, ENU,
// and the geographic-grid placement against the OGR path (terrain/georef.h).
#include "io/filter/geodesy.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include "terrain/dem_loader.h"
#include "terrain/georef.h"
#include "terrain/heightfield.h"

namespace {

using namespace ig::io::geo;

// Uniform double in [lo, hi) from raw mt19937_64 output (distributions are not
// portable across standard libraries; the raw engine output is).
struct Rng {
  std::mt19937_64 eng;
  explicit Rng(std::uint64_t seed) : eng(seed) {}
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(eng() >> 11) * (1.0 / 9007199254740992.0));
  }
};

TEST(Geodesy, KnownEcefValues) {
  glm::dvec3 e = geodetic_to_ecef({0.0, 0.0, 0.0});
  EXPECT_NEAR(e.x, 6378137.0, 1e-9);
  EXPECT_NEAR(e.y, 0.0, 1e-9);
  EXPECT_NEAR(e.z, 0.0, 1e-9);
  e = geodetic_to_ecef({90.0, 0.0, 0.0});
  EXPECT_NEAR(e.x, 0.0, 1e-6);
  EXPECT_NEAR(e.y, 0.0, 1e-6);
  EXPECT_NEAR(e.z, 6356752.314245, 1e-6);
  e = geodetic_to_ecef({-90.0, 0.0, 100.0});
  EXPECT_NEAR(e.z, -6356852.314245, 1e-6);
  e = geodetic_to_ecef({0.0, 90.0, 1000.0});
  EXPECT_NEAR(e.x, 0.0, 1e-6);
  EXPECT_NEAR(e.y, 6379137.0, 1e-9);
  e = geodetic_to_ecef({0.0, 180.0, 0.0});
  EXPECT_NEAR(e.x, -6378137.0, 1e-9);
  // 45 N 45 E, h 0: N = a / sqrt(1 - e2/2); x = y = N cos45 cos45 = N/2.
  const double n45 = kWgs84A / std::sqrt(1.0 - kWgs84E2 * 0.5);
  e = geodetic_to_ecef({45.0, 45.0, 0.0});
  EXPECT_NEAR(e.x, n45 / 2.0, 1e-8);
  EXPECT_NEAR(e.y, n45 / 2.0, 1e-8);
  EXPECT_NEAR(e.z, n45 * (1.0 - kWgs84E2) * std::sqrt(0.5), 1e-8);

  const Geodetic np = ecef_to_geodetic({0.0, 0.0, 6356752.314245 + 50.0});
  EXPECT_NEAR(np.lat_deg, 90.0, 1e-12);
  EXPECT_NEAR(np.height_m, 50.0, 1e-6);
  const Geodetic eq = ecef_to_geodetic({6378137.0, 0.0, 0.0});
  EXPECT_NEAR(eq.lat_deg, 0.0, 1e-12);
  EXPECT_NEAR(eq.lon_deg, 0.0, 1e-12);
  EXPECT_NEAR(eq.height_m, 0.0, 1e-6);
}

TEST(Geodesy, RoundTripRandomPoints) {
  Rng rng(20240601);
  double max_lat = 0, max_lon = 0, max_h = 0;
  for (int k = 0; k < 200000; ++k) {
    Geodetic g{rng.uniform(-90.0, 90.0), rng.uniform(-180.0, 180.0), rng.uniform(-500.0, 50000.0)};
    if (k % 10 == 0) g.height_m = rng.uniform(-10000.0, 1000000.0);  // some far from the surface
    const Geodetic r = ecef_to_geodetic(geodetic_to_ecef(g));
    max_lat = std::max(max_lat, std::fabs(r.lat_deg - g.lat_deg));
    double dl = std::fabs(r.lon_deg - g.lon_deg);
    dl = std::min(dl, 360.0 - dl);
    if (std::fabs(g.lat_deg) < 89.9999) max_lon = std::max(max_lon, dl);
    max_h = std::max(max_h, std::fabs(r.height_m - g.height_m));
  }
  std::printf("[geodesy] round trip over 200000 points: max |dlat| %.3g deg, |dlon| %.3g deg, "
              "|dh| %.3g m\n", max_lat, max_lon, max_h);
  EXPECT_LT(max_lat, 1e-9);
  EXPECT_LT(max_lon, 1e-9);
  EXPECT_LT(max_h, 1e-6);
}

TEST(Geodesy, EnuRoundTripAndAxes) {
  Rng rng(7);
  for (int k = 0; k < 2000; ++k) {
    const Geodetic o{rng.uniform(-89.0, 89.0), rng.uniform(-180.0, 180.0), rng.uniform(-100.0, 5000.0)};
    const EnuFrame f(o);
    const glm::dvec3 at = f.geodetic_to_enu(o);
    EXPECT_LT(glm::length(at), 1e-6);
    const glm::dvec3 enu{rng.uniform(-50000, 50000), rng.uniform(-50000, 50000), rng.uniform(-1000, 15000)};
    const Geodetic g = f.enu_to_geodetic(enu);
    const glm::dvec3 back = f.geodetic_to_enu(g);
    EXPECT_LT(glm::length(back - enu), 1e-6);
  }
  // Direction rotation is orthonormal.
  const EnuFrame f({37.0, -118.0, 1200.0});
  const glm::dvec3 d{3.0, -4.0, 12.0};
  EXPECT_NEAR(glm::length(f.enu_dir_to_ecef(d)), 13.0, 1e-12);
  const glm::dvec3 rt = f.ecef_dir_to_enu(f.enu_dir_to_ecef(d));
  EXPECT_LT(glm::length(rt - d), 1e-12);
}

TEST(Geodesy, EnuOneKilometreNorthDropsWithCurvature) {
  const Geodetic o{37.0, -118.0, 1200.0};
  const EnuFrame f(o);
  const MetresPerDegree mpd = metres_per_degree(o.lat_deg);
  // 1000 m of arc along the meridian (at the origin's height the arc radius is M + h).
  const double dlat = 1000.0 / (mpd.north * (1.0 + o.height_m / (mpd.north * 180.0 / M_PI)));
  const glm::dvec3 enu = f.geodetic_to_enu({o.lat_deg + dlat, o.lon_deg, o.height_m});
  std::printf("[geodesy] 1 km north at 37N: ENU (%.6f, %.6f, %.6f)\n", enu.x, enu.y, enu.z);
  EXPECT_NEAR(enu.x, 0.0, 1e-6);
  EXPECT_NEAR(enu.y, 1000.0, 1e-3);     // chord of a 1 km arc: 1000 - 1e-6 m
  EXPECT_NEAR(enu.z, -0.0785, 0.0015);  // s^2 / (2 R), R ~ 6.36e6 m
  EXPECT_LT(enu.z, 0.0);
  // 1 km east: drop is s^2 / (2 N) with N the prime-vertical radius.
  const double dlon = 1000.0 / (mpd.east * (1.0 + o.height_m / (mpd.east * 180.0 / M_PI / std::cos(o.lat_deg * M_PI / 180.0))));
  const glm::dvec3 e2 = f.geodetic_to_enu({o.lat_deg, o.lon_deg + dlon, o.height_m});
  EXPECT_NEAR(e2.x, 1000.0, 0.05);
  EXPECT_NEAR(e2.z, -0.0785, 0.0015);
}

TEST(Geodesy, MetresPerDegreeMatchesDemLoader) {
  for (double lat = -89.0; lat <= 89.0; lat += 0.5) {
    const MetresPerDegree a = metres_per_degree(lat);
    const ig::terrain::MetresPerAngle b = ig::terrain::metres_per_angle(lat);
    EXPECT_NEAR(a.north, b.north, 1e-9 * b.north);
    EXPECT_NEAR(a.east, b.east, 1e-9 * b.north);
  }
}

// A geographic EPSG:4326 heightfield georeference laid out like dem_loader
// does it: 1 arc-second samples, north-up file rows flipped to south-up.
ig::terrain::Heightfield make_geographic_hf(double west, double north, int w, int h, double px_deg) {
  ig::terrain::Heightfield hf;
  hf.width = w;
  hf.height = h;
  hf.heights.assign(static_cast<std::size_t>(w) * h, 0.0f);
  const double gt[6] = {west, px_deg, 0.0, north, 0.0, -px_deg};
  ig::terrain::GeoReference geo;
  OGRSpatialReference srs;
  srs.importFromEPSG(4326);
  char* wkt = nullptr;
  srs.exportToWkt(&wkt);
  geo.crs_wkt = wkt;
  CPLFree(wkt);
  geo.crs_name = "EPSG:4326";
  geo.geographic = true;
  geo.grid_to_crs = {gt[0] + 0.5 * gt[1] + (h - 0.5) * gt[2], gt[1], -gt[2],
                     gt[3] + 0.5 * gt[4] + (h - 0.5) * gt[5], gt[4], -gt[5]};
  const double centre_lat = gt[3] + 0.5 * w * gt[4] + 0.5 * h * gt[5];
  const ig::terrain::MetresPerAngle mpa = ig::terrain::metres_per_angle(centre_lat);
  hf.spacing_x_m = std::hypot(gt[1] * mpa.east, gt[4] * mpa.north);
  hf.spacing_y_m = std::hypot(gt[2] * mpa.east, gt[5] * mpa.north);
  hf.georef = geo;
  return hf;
}

TEST(Geodesy, GeographicGridMatchesOgrPath) {
  const double px = 1.0 / 3600.0;
  const auto hf = make_geographic_hf(-118.5, 37.5, 1801, 1201, px);
  const auto grid = GeographicGrid::make(hf.georef->grid_to_crs, hf.spacing_x_m, hf.spacing_y_m);
  ASSERT_TRUE(grid.has_value());
  Rng rng(99);
  double max_err = 0;
  for (int k = 0; k < 500; ++k) {
    const double lat = rng.uniform(37.5 - 1201 * px, 37.5);
    const double lon = rng.uniform(-118.5, -118.5 + 1801 * px);
    const auto ogr = ig::terrain::geodetic_to_local(hf, lat, lon);
    ASSERT_TRUE(ogr.has_value());
    const glm::dvec2 fast = grid->to_local(lat, lon);
    max_err = std::max(max_err, glm::length(fast - *ogr));
    const Geodetic back = grid->from_local({fast.x, fast.y, 12.0});
    EXPECT_NEAR(back.lat_deg, lat, 1e-12);
    EXPECT_NEAR(back.lon_deg, lon, 1e-12);
    EXPECT_EQ(back.height_m, 12.0);
  }
  std::printf("[geodesy] fast grid placement vs OGR geodetic_to_local: max diff %.3g m\n", max_err);
  EXPECT_LT(max_err, 1e-6);
  // Sample centres land on integer multiples of the spacing.
  const glm::dvec2 ij = grid->to_index(hf.georef->grid_to_crs[3] + 7 * hf.georef->grid_to_crs[5],
                                       hf.georef->grid_to_crs[0] + 11 * hf.georef->grid_to_crs[1]);
  EXPECT_NEAR(ij.x, 11.0, 1e-9);
  EXPECT_NEAR(ij.y, 7.0, 1e-9);
}

TEST(Geodesy, GeographicGridAgreesWithEnuNearDemCentre) {
  // Near the DEM centre the grid's local metres and true ENU at the centre
  // agree to second order: |error| <~ d^2 / R (~0.16 m at 1 km, ~4 m at 5 km,
  // the flat-grid approximation the DEM mesh itself makes).
  const double px = 1.0 / 3600.0;
  const int w = 3601, h = 3601;
  const auto hf = make_geographic_hf(-119.0, 38.0, w, h, px);
  const auto grid = *GeographicGrid::make(hf.georef->grid_to_crs, hf.spacing_x_m, hf.spacing_y_m);
  const double clat = 38.0 - 0.5 * h * px, clon = -119.0 + 0.5 * w * px;
  const EnuFrame enu({clat, clon, 0.0});
  const glm::dvec2 c = grid.to_local(clat, clon);
  Rng rng(5);
  double max1 = 0, max5 = 0;
  for (int k = 0; k < 2000; ++k) {
    const double r = (k % 2) ? 1000.0 : 5000.0;
    const double e = rng.uniform(-r, r), n = rng.uniform(-r, r);
    const Geodetic g = enu.enu_to_geodetic({e, n, 0.0});
    const glm::dvec2 p = grid.to_local(g.lat_deg, g.lon_deg) - c;
    const glm::dvec3 t = enu.geodetic_to_enu({g.lat_deg, g.lon_deg, 0.0});
    const double err = std::hypot(p.x - t.x, p.y - t.y);
    (r < 2000 ? max1 : max5) = std::max(r < 2000 ? max1 : max5, err);
  }
  std::printf("[geodesy] grid vs ENU at DEM centre: max horiz diff %.4f m within 1 km, %.4f m within 5 km\n",
              max1, max5);
  EXPECT_LT(max1, 0.3);
  EXPECT_LT(max5, 6.0);
  // Exactly at the centre: one grid step east/north is one spacing.
  const glm::dvec2 step = grid.to_local(clat + px, clon + px) - c;
  EXPECT_NEAR(step.x, hf.spacing_x_m, 1e-6);
  EXPECT_NEAR(step.y, hf.spacing_y_m, 1e-6);
}

TEST(Geodesy, GeographicGridRejectsBadInput) {
  EXPECT_FALSE(GeographicGrid::make({0, 0, 0, 0, 0, 0}, 1, 1).has_value());
  EXPECT_FALSE(GeographicGrid::make({0, 1, 0, 0, 0, 1}, 0, 1).has_value());
  EXPECT_FALSE(GeographicGrid::make({NAN, 1, 0, 0, 0, 1}, 1, 1).has_value());
}

TEST(Geodesy, GeographicGridAcrossAntimeridian) {
  const double px = 1.0 / 3600.0;
  const auto hf = make_geographic_hf(179.5, -16.0, 3601, 1001, px);  // Fiji: 179.5 .. 180.5
  const auto grid = *GeographicGrid::make(hf.georef->grid_to_crs, hf.spacing_x_m, hf.spacing_y_m);
  const glm::dvec2 a = grid.to_local(-16.1, 179.9);
  const glm::dvec2 b = grid.to_local(-16.1, -179.9);  // 0.2 deg further east
  EXPECT_NEAR(b.x - a.x, 0.2 / px * hf.spacing_x_m, 1e-6);
}

}  // namespace
