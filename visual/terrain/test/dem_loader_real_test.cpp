// The real DEMs in $IG_DEM_DIR (see shared/data/dem/README.md), checked
// against the README when it is set.
#include "terrain/dem_loader.h"

#include <gtest/gtest.h>

#include "terrain/test/dem_loader_test_support.h"

namespace {

using namespace dem_test;

// --------------------------------------------------------- real DEMs ---

struct Expect {
  int w, h;
  float min_m, max_m, tol_m;
  double sx_lo, sx_hi, sy_lo, sy_hi;
  std::int64_t nodata;
  const char* crs;  // nullptr: none
  DemLoadOptions opts;
};

std::map<std::string, Expect> real_expectations() {
  DemLoadOptions plus1000;
  plus1000.encoding = "png16";
  plus1000.offset = -1000.0;
  // Spacing bounds: N-S 3" arc is 92.3..92.7 m at these latitudes on WGS84
  // (the README's 92.6 is the spherical mean); E-W from the README per file.
  return {
      {"sierra_nevada_3arcsec_4097.tif",
       {4097, 4097, -80, 4404, 0, 72.5, 74.5, 92.3, 92.8, 0, "EPSG:4326", {}}},
      {"sierra_nevada_3arcsec_4097_u16_plus1000.png",
       {4097, 4097, -80, 4404, 0, 1, 1, 1, 1, 0, nullptr, plus1000}},
      {"mt_rainier_90m.tif", {1201, 1201, 263, 4371, 0, 63, 64.7, 92.3, 92.8, 9033, "EPSG:4326", {}}},
      {"mt_everest_90m.tif",
       {1201, 1201, 192, 8642, 0, 81.5, 83, 92.3, 92.8, 130953, "EPSG:4326", {}}},
      {"mt_fuji_90m.tif", {1201, 1201, -16, 3742, 0, 75, 76.2, 92.3, 92.8, 2437, "EPSG:4326", {}}},
      {"N44W072.hgt", {1201, 1201, 115, 1908, 0, 65.5, 66.8, 92.3, 92.8, 0, "EPSG:4326", {}}},
      {"qgis_dem25_bejar_spain.tif",
       {601, 410, 514, 2410, 1.0f, 25, 25, 25, 25, 0, "EPSG:23030", {}}},
      {"fuji.png", {512, 512, 13.7f, 3751.0f, 0.05f, 1, 1, 1, 1, 0, nullptr, {}}},
  };
}

const char* dem_dir() {
  const char* d = std::getenv("IG_DEM_DIR");
  return (d && *d) ? d : nullptr;
}

TEST(RealDems, EveryFileMatchesTheReadme) {
  const char* dir = dem_dir();
  if (!dir) GTEST_SKIP() << "IG_DEM_DIR not set: real-DEM tests skipped";
  const auto expect = real_expectations();
  const std::vector<std::string> dem_ext = {".tif", ".tiff", ".hgt", ".png", ".asc", ".dem"};
  int found = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (!entry.is_regular_file() ||
        std::find(dem_ext.begin(), dem_ext.end(), ext) == dem_ext.end())
      continue;
    ++found;
    const std::string name = entry.path().filename().string();
    SCOPED_TRACE(name);
    const auto it = expect.find(name);
    const DemLoadOptions opts = it != expect.end() ? it->second.opts : DemLoadOptions{};
    Heightfield hf;
    ASSERT_NO_THROW(hf = load_dem(entry.path().string(), opts));
    expect_no_nan(hf);
    if (it == expect.end()) {
      ADD_FAILURE() << "no README expectations for " << name;
      continue;
    }
    const Expect& e = it->second;
    EXPECT_EQ(hf.width, e.w);
    EXPECT_EQ(hf.height, e.h);
    EXPECT_NEAR(hf.min_m, e.min_m, e.tol_m);
    EXPECT_NEAR(hf.max_m, e.max_m, e.tol_m);
    EXPECT_GE(hf.spacing_x_m, e.sx_lo);
    EXPECT_LE(hf.spacing_x_m, e.sx_hi);
    EXPECT_GE(hf.spacing_y_m, e.sy_lo);
    EXPECT_LE(hf.spacing_y_m, e.sy_hi);
    // README says "no voids", but the osgEarth tiles do have SRTM voids
    // (gdalinfo -stats: STATISTICS_VALID_PERCENT 90.92 / 99.83 / 99.37).
    EXPECT_EQ(hf.nodata_count, e.nodata);
    if (e.crs) {
      ASSERT_TRUE(hf.georef);
      EXPECT_EQ(hf.georef->crs_name, e.crs);
    } else {
      EXPECT_FALSE(hf.georef);
    }
  }
  EXPECT_GE(found, 8) << "expected the 8 README DEMs in " << dir;
}

TEST(RealDems, SierraPngEqualsGeoTiff) {
  const char* dir = dem_dir();
  if (!dir) GTEST_SKIP() << "IG_DEM_DIR not set: real-DEM tests skipped";
  DemLoadOptions o;
  o.scale = 1.0;
  o.offset = -1000.0;
  const Heightfield png =
      load_dem((fs::path(dir) / "sierra_nevada_3arcsec_4097_u16_plus1000.png").string(), o);
  const Heightfield tif = load_dem((fs::path(dir) / "sierra_nevada_3arcsec_4097.tif").string());
  EXPECT_EQ(png.min_m, tif.min_m);
  EXPECT_EQ(png.max_m, tif.max_m);
  EXPECT_TRUE(png.heights == tif.heights) << "PNG and GeoTIFF samples differ";
}

TEST(RealDems, HgtGeoreferenceFromTheFileName) {
  const char* dir = dem_dir();
  if (!dir) GTEST_SKIP() << "IG_DEM_DIR not set: real-DEM tests skipped";
  const Heightfield hf = load_dem((fs::path(dir) / "N44W072.hgt").string());
  ASSERT_TRUE(hf.georef);
  EXPECT_NEAR(hf.georef->grid_to_crs[0], -72.0, 1e-9);
  EXPECT_NEAR(hf.georef->grid_to_crs[3], 44.0, 1e-9);
  EXPECT_NEAR(hf.georef->grid_to_crs[3] + 1200 * hf.georef->grid_to_crs[5], 45.0, 1e-9);
}

TEST(RealDems, NonDemFileFailsCleanly) {
  const char* dir = dem_dir();
  if (!dir) GTEST_SKIP() << "IG_DEM_DIR not set: real-DEM tests skipped";
  const std::string readme = (fs::path(dir) / "README.md").string();
  if (!fs::exists(readme)) GTEST_SKIP() << "no README.md in " << dir;
  expect_dem_error(readme, "not a recognised raster format");
}

}  // namespace
