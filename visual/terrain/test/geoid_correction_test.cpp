// Ellipsoidal DEM heights reduced to the EGM96 geoid at load
// (terrain/geoid_correction.h): against PROJ's own vertical transformation
// (WGS 84 ellipsoidal height -> EGM96 height, EPSG:4979 -> EPSG:4326+5773),
// the same in the whole and the paged load, heights as stored by default,
// clear errors where the geoid cannot apply.
#include "terrain/geoid_correction.h"

#include <gtest/gtest.h>

#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "terrain/dem_loader.h"
#include "terrain/test/test_geotiff.h"

namespace ig::terrain {
namespace {

constexpr int kW = 601, kH = 481;  // 0.5 x 0.4 degrees west of 118.5 W, south of 37.5 N

std::string write_flat(const std::string& name, float height_m) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::vector<float> h(std::size_t(kW) * kH, height_m);
  h[std::size_t(200) * kW + 300] = -9999.0f;  // one void: filled after the correction
  test::write_test_geotiff(path, kW, kH, h, -9999.0);
  return path;
}

// PROJ's EGM96 height of a point at ellipsoidal height h (lon, lat degrees).
double proj_orthometric(double lon, double lat, double h) {
  OGRSpatialReferenceH src = OSRNewSpatialReference(nullptr), dst = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(src, 4979);
  OSRSetFromUserInput(dst, "EPSG:4326+5773");
  OSRSetAxisMappingStrategy(src, OAMS_TRADITIONAL_GIS_ORDER);
  OSRSetAxisMappingStrategy(dst, OAMS_TRADITIONAL_GIS_ORDER);
  OGRCoordinateTransformationH t = OCTNewCoordinateTransformation(src, dst);
  double x = lon, y = lat, z = h;
  const bool ok = t && OCTTransform(t, 1, &x, &y, &z);
  if (t) OCTDestroyCoordinateTransformation(t);
  OSRDestroySpatialReference(src);
  OSRDestroySpatialReference(dst);
  return ok ? z : NAN;
}

TEST(GeoidCorrection, EllipsoidalHeightsAgreeWithProjsVerticalTransformation) {
  if (GeoidCorrection::find_grid_file().empty()) GTEST_SKIP() << "egm96_15.gtx not installed (Debian package proj-data)";
  const std::string path = write_flat("ig_geoid_flat.tif", 1000.0f);
  DemLoadOptions opts;
  opts.vertical_datum = "ellipsoid";
  const Heightfield hf = load_dem(path, opts);
  ASSERT_TRUE(hf.georef);
  double lo = 1e9, hi = -1e9, worst = 0.0;
  for (int j : {0, 120, 240, 480})
    for (int i : {0, 150, 300, 600}) {
      // Sample (i, j), j = 0 south: lon, lat of its centre.
      const double lon = -119.0 + (i + 0.5) / 1200.0, lat = 37.5 - (kH - 1 - j + 0.5) / 1200.0;
      const double expected = proj_orthometric(lon, lat, 1000.0);
      ASSERT_TRUE(std::isfinite(expected));
      ASSERT_NE(expected, 1000.0) << "PROJ applied no geoid: its EGM96 grid is missing";
      // Bilinear between nodes every 32 samples of PROJ's bilinear grid: within a few cm.
      EXPECT_NEAR(hf.at(i, j), expected, 0.05) << "sample " << i << "," << j;
      worst = std::max(worst, std::abs(hf.at(i, j) - expected));
      lo = std::min(lo, 1000.0 - hf.at(i, j));
      hi = std::max(hi, 1000.0 - hf.at(i, j));
    }
  // EGM96 over the Sierra Nevada: the geoid 25-35 m below the ellipsoid, varying across half a degree.
  EXPECT_LT(hi, -20.0);
  EXPECT_GT(lo, -40.0);
  EXPECT_GT(hi - lo, 0.1);
  std::printf("EGM96 undulation over the test DEM: %.2f .. %.2f m; largest difference from PROJ %.3f m\n", lo, hi, worst);
  EXPECT_EQ(hf.nodata_count, 1);  // the void filled from corrected neighbours
  EXPECT_NEAR(hf.at(300, kH - 1 - 200), hf.at(301, kH - 1 - 200), 0.01);
  std::filesystem::remove(path);
}

TEST(GeoidCorrection, HeightsAsStoredByDefaultAndTheSameWhenPaged) {
  if (GeoidCorrection::find_grid_file().empty()) GTEST_SKIP() << "egm96_15.gtx not installed (Debian package proj-data)";
  const std::string path = write_flat("ig_geoid_paged.tif", 500.0f);
  const Heightfield as_stored = load_dem(path);
  EXPECT_EQ(as_stored.min_m, 500.0f);
  EXPECT_EQ(as_stored.max_m, 500.0f);
  DemLoadOptions whole_opts;
  whole_opts.vertical_datum = "ellipsoid";
  const Heightfield whole = load_dem(path, whole_opts);
  DemLoadOptions paged_opts = whole_opts;
  paged_opts.memory_budget_mb = 1;  // 1.15 MB of floats: paged
  paged_opts.page_tile = 64;
  const Heightfield paged = load_dem(path, paged_opts);
  ASSERT_TRUE(paged.paged);
  EXPECT_EQ(paged.min_m, whole.min_m);
  EXPECT_EQ(paged.max_m, whole.max_m);
  for (int j = 0; j < kH; j += 7)
    for (int i = 0; i < kW; i += 5) ASSERT_EQ(paged.at(i, j), whole.at(i, j)) << i << "," << j;
  std::filesystem::remove(path);
}

TEST(GeoidCorrection, NeedsAGeoreferencedDemAndAKnownDatum) {
  const std::string path = (std::filesystem::temp_directory_path() / "ig_geoid_plain.tif").string();
  GDALAllRegister();
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), 8, 8, 1, GDT_Float32, nullptr);
  ASSERT_NE(ds, nullptr);
  std::vector<float> h(64, 10.0f);
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, 8, 8, h.data(), 8, 8, GDT_Float32, 0, 0), CE_None);
  GDALClose(ds);
  DemLoadOptions opts;
  opts.vertical_datum = "ellipsoid";
  try {
    load_dem(path, opts);
    ADD_FAILURE() << "an ungeoreferenced DEM with ellipsoidal heights must be refused";
  } catch (const DemError& e) {
    EXPECT_NE(std::string(e.what()).find("needs a georeferenced DEM"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  opts.vertical_datum = "navd88";
  EXPECT_THROW(load_dem(path, opts), DemError);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace ig::terrain
