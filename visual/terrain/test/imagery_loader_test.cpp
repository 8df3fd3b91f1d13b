// Imagery draped over a DEM (terrain/imagery_loader.h): georeferenced images
// of another extent, resolution or CRS land on the DEM's samples; images
// without georeferencing span the DEM; non-overlapping ones are refused.
#include <gtest/gtest.h>

#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "terrain/dem_loader.h"
#include "terrain/imagery_loader.h"

namespace {

namespace fs = std::filesystem;

// A 1/1200-degree DEM whose north-west sample centre is at (-118, 37).
constexpr double kRes = 1.0 / 1200.0;
ig::terrain::Heightfield dem(int w, int h) {
  ig::terrain::Heightfield hf;
  hf.width = w;
  hf.height = h;
  hf.heights.assign(std::size_t(w) * h, 100.0f);
  hf.spacing_x_m = 74.0;
  hf.spacing_y_m = 92.6;
  ig::terrain::GeoReference g;
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(srs, 4326);
  char* wkt = nullptr;
  OSRExportToWkt(srs, &wkt);
  g.crs_wkt = wkt;
  CPLFree(wkt);
  OSRDestroySpatialReference(srs);
  g.geographic = true;
  // (i, j) with j = 0 south -> lon, lat of the sample centre.
  g.grid_to_crs = {-118.0, kRes, 0.0, 37.0 - (h - 1) * kRes, 0.0, kRes};
  hf.georef = g;
  hf.finalize_stats();
  return hf;
}

// Colour of a place: red by longitude, green by latitude, over a 0.1 degree square.
std::array<double, 2> colour_of(double lon, double lat) {
  return {(lon + 118.0) / 0.1 * 255.0, (lat - 36.9) / 0.1 * 255.0};
}

// Writes an RGB GeoTIFF of w x h pixels in EPSG:epsg with geotransform gt,
// each pixel coloured by colour_of its centre's lon/lat.
std::string write_image(const std::string& name, int epsg, const double gt[6], int w, int h) {
  GDALAllRegister();
  const std::string path = (fs::temp_directory_path() / name).string();
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), w, h, 3, GDT_Byte, nullptr);
  GDALSetGeoTransform(ds, const_cast<double*>(gt));
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr), wgs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(srs, epsg);
  OSRImportFromEPSG(wgs, 4326);
  OSRSetAxisMappingStrategy(srs, OAMS_TRADITIONAL_GIS_ORDER);
  OSRSetAxisMappingStrategy(wgs, OAMS_TRADITIONAL_GIS_ORDER);
  GDALSetSpatialRef(ds, srs);
  OGRCoordinateTransformationH to_wgs = OCTNewCoordinateTransformation(srs, wgs);
  std::vector<std::uint8_t> r(std::size_t(w) * h), g(r.size()), b(r.size(), 60);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double px = gt[0] + (x + 0.5) * gt[1], py = gt[3] + (y + 0.5) * gt[5];
      OCTTransform(to_wgs, 1, &px, &py, nullptr);
      const auto c = colour_of(px, py);
      r[y * w + x] = std::uint8_t(std::clamp(c[0], 0.0, 255.0));
      g[y * w + x] = std::uint8_t(std::clamp(c[1], 0.0, 255.0));
    }
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(ds, k + 1), GF_Write, 0, 0, w, h, (k == 0 ? r : k == 1 ? g : b).data(), w,
                           h, GDT_Byte, 0, 0),
              CE_None);
  OCTDestroyCoordinateTransformation(to_wgs);
  OSRDestroySpatialReference(srs);
  OSRDestroySpatialReference(wgs);
  GDALClose(ds);
  return path;
}

// Every DEM sample's imagery texel has the colour of the sample's place.
void expect_on_samples(const ig::terrain::Heightfield& hf, const ig::terrain::Imagery& img, double tolerance) {
  ASSERT_EQ(img.rgb.size(), std::size_t(img.width) * img.height * 3);
  double worst = 0.0;
  for (int j = 2; j < hf.height - 2; j += 3)
    for (int i = 2; i < hf.width - 2; i += 3) {
      // The texel the shader reads for sample (i, j): (s + 0.5) / dem_size.
      const int x = int((i + 0.5) / hf.width * img.width), y = int((j + 0.5) / hf.height * img.height);
      const auto& g = hf.georef->grid_to_crs;
      const auto want = colour_of(g[0] + i * g[1], g[3] + j * g[5]);
      const std::uint8_t* px = &img.rgb[(std::size_t(y) * img.width + x) * 3];
      worst = std::max({worst, std::abs(px[0] - want[0]), std::abs(px[1] - want[1])});
    }
  EXPECT_LE(worst, tolerance);
}

TEST(ImageryLoader, GeographicImageOfALargerExtentAndFinerResolutionLandsOnTheSamples) {
  const auto hf = dem(61, 49);
  // 3x finer, starting 0.01 degree west and north of the DEM.
  const double gt[6] = {-118.0 - 0.5 * kRes - 0.01, kRes / 3, 0, 37.0 + 0.5 * kRes + 0.01, 0, -kRes / 3};
  const auto path = write_image("ig_imagery_geo.tif", 4326, gt, 400, 400);
  const auto img = ig::terrain::load_imagery(hf, path, 16384);
  EXPECT_TRUE(img.warped);
  EXPECT_EQ(img.uncovered, 0);
  EXPECT_GE(img.width, 3 * 61 - 3);
  expect_on_samples(hf, img, 3.0);
  fs::remove(path);
}

// Beyond the texture limit (issue 16): the full resolution is kept as the
// one-texture load has it, the overview is its step x step box mean (fewer
// pixels in the last row and column), and both land on the samples.
TEST(ImageryLoader, ImageBeyondTheLimitKeepsFullResolutionAndABoxMeanOverview) {
  const auto hf = dem(61, 49);
  const double gt[6] = {-118.0 - 0.5 * kRes - 0.01, kRes / 3, 0, 37.0 + 0.5 * kRes + 0.01, 0, -kRes / 3};
  const auto path = write_image("ig_imagery_beyond.tif", 4326, gt, 400, 400);
  const auto whole = ig::terrain::load_imagery(hf, path, 16384);
  const auto img = ig::terrain::load_imagery(hf, path, 50);  // step 4: 183 = 45 * 4 + 3, a partial block
  EXPECT_TRUE(whole.full_rgb.empty());
  EXPECT_EQ(whole.full_step, 1);
  ASSERT_GT(img.full_step, 1);
  EXPECT_LE(img.width, 50);
  EXPECT_LE(img.height, 50);
  EXPECT_EQ(img.full_width(), whole.width);
  EXPECT_EQ(img.full_height(), whole.height);
  EXPECT_EQ(img.full_rgb, whole.rgb);
  const int f = img.full_step, fw = img.full_width(), fh = img.full_height();
  EXPECT_NE(fw % f, 0);  // the last column is a partial block
  EXPECT_EQ(img.width, (fw + f - 1) / f);
  EXPECT_EQ(img.height, (fh + f - 1) / f);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) {
        int sum = 0, n = 0;
        for (int v = y * f; v < std::min(fh, (y + 1) * f); ++v)
          for (int u = x * f; u < std::min(fw, (x + 1) * f); ++u, ++n) sum += img.full_rgb[(std::size_t(v) * fw + u) * 3 + c];
        ASSERT_EQ(img.rgb[(std::size_t(y) * img.width + x) * 3 + c], (sum + n / 2) / n) << x << "," << y;
      }
  fs::remove(path);
}

TEST(ImageryLoader, UtmImageIsReprojectedOntoTheDem) {
  const auto hf = dem(61, 49);
  // UTM 11N around (-118 + 0.025, 37 - 0.02): easting ~ 411 km, northing ~ 4092 km; 30 m pixels.
  const double gt[6] = {409500.0, 30.0, 0.0, 4096500.0, 0.0, -30.0};
  const auto path = write_image("ig_imagery_utm.tif", 32611, gt, 300, 300);
  const auto img = ig::terrain::load_imagery(hf, path, 16384);
  EXPECT_TRUE(img.warped);
  expect_on_samples(hf, img, 4.0);
  fs::remove(path);
}

TEST(ImageryLoader, ImageElsewhereIsRefusedAndPlainImagesSpanTheDem) {
  const auto hf = dem(61, 49);
  const double far_away[6] = {10.0, kRes, 0, 50.0, 0, -kRes};
  const auto path = write_image("ig_imagery_far.tif", 4326, far_away, 50, 50);
  try {
    ig::terrain::load_imagery(hf, path, 16384);
    ADD_FAILURE() << "imagery far from the DEM was accepted";
  } catch (const ig::terrain::DemError& e) {
    EXPECT_NE(std::string(e.what()).find("does not overlap the DEM"), std::string::npos) << e.what();
  }
  fs::remove(path);
  // No georeferencing: taken as spanning the DEM, rows flipped south first.
  const std::string plain = (fs::temp_directory_path() / "ig_imagery_plain.tif").string();
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), plain.c_str(), 4, 3, 1, GDT_Byte, nullptr);
  std::vector<std::uint8_t> grey = {0, 0, 0, 0, 50, 50, 50, 50, 200, 200, 200, 200};  // north row first
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, 4, 3, grey.data(), 4, 3, GDT_Byte, 0, 0), CE_None);
  GDALClose(ds);
  const auto img = ig::terrain::load_imagery(hf, plain, 16384);
  EXPECT_FALSE(img.warped);
  EXPECT_EQ(img.width, 4);
  EXPECT_EQ(img.rgb[0], 200);                  // south row first
  EXPECT_EQ(img.rgb[(2 * 4) * 3 + 1], 0);      // north row last, grey in every channel
  fs::remove(plain);
  EXPECT_THROW(ig::terrain::load_imagery(hf, "/nonexistent/x.tif", 16384), ig::terrain::DemError);
}

}  // namespace
