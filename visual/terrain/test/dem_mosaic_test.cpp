// Folders of DEM tiles (terrain/dem_mosaic.h) on small GeoTIFFs written here:
// the mosaic equals the whole grid sample for sample, gaps are counted
// nodata, and bad folders fail with the file and the reason.
#include <gtest/gtest.h>

#include <gdal.h>
#include <ogr_srs_api.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "terrain/dem_loader.h"

namespace {

namespace fs = std::filesystem;

// Height of the whole grid at column c, row r (row 0 north), as written.
float height(int c, int r) { return float(100.0 + 3.0 * c + 0.5 * r * r - 7.0 * std::sin(0.3 * c * r)); }

// Writes columns [c0, c1) x rows [r0, r1) of a 1/1200-degree WGS 84 grid whose
// north-west corner is at (-118, 37), as a float GeoTIFF.
void write_tile(const std::string& path, int c0, int c1, int r0, int r1) {
  GDALAllRegister();
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), c1 - c0, r1 - r0, 1, GDT_Float32, nullptr);
  ASSERT_NE(ds, nullptr);
  const double res = 1.0 / 1200.0;
  double gt[6] = {-118.0 + c0 * res, res, 0, 37.0 - r0 * res, 0, -res};
  GDALSetGeoTransform(ds, gt);
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(srs, 4326);
  GDALSetSpatialRef(ds, srs);
  OSRDestroySpatialReference(srs);
  std::vector<float> v;
  for (int r = r0; r < r1; ++r)
    for (int c = c0; c < c1; ++c) v.push_back(height(c, r));
  EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, c1 - c0, r1 - r0, v.data(), c1 - c0, r1 - r0,
                         GDT_Float32, 0, 0),
            CE_None);
  GDALClose(ds);
}

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name) : path(fs::temp_directory_path() / ("ig_mosaic_" + name)) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string file(const std::string& n) const { return (path / n).string(); }
};

TEST(DemMosaic, MixedTileSizesEqualTheWholeGridSampleForSample) {
  TempDir d("whole");
  // 37 x 29 samples cut at column 20 and row 11: four tiles of different sizes.
  write_tile(d.file("nw.tif"), 0, 20, 0, 11);
  write_tile(d.file("ne.tif"), 20, 37, 0, 11);
  write_tile(d.file("sw.tif"), 0, 20, 11, 29);
  write_tile(d.file("se.tif"), 20, 37, 11, 29);
  std::ofstream(d.file("README.txt")) << "ignored\n";
  const auto hf = ig::terrain::load_dem(d.path.string());
  ASSERT_EQ(hf.width, 37);
  ASSERT_EQ(hf.height, 29);
  EXPECT_EQ(hf.source_tiles, 4);
  EXPECT_EQ(hf.nodata_count, 0);
  for (int j = 0; j < hf.height; ++j)
    for (int i = 0; i < hf.width; ++i) ASSERT_EQ(hf.at(i, j), height(i, 28 - j)) << i << ", " << j;  // row 0 = south
  ASSERT_TRUE(hf.georef.has_value());
  EXPECT_NEAR(hf.georef->grid_to_crs[0], -118.0 + 0.5 / 1200.0, 1e-12);  // west sample centre
}

TEST(DemMosaic, AMissingTileIsNodataFilledAndCounted) {
  TempDir d("missing");
  write_tile(d.file("a.tif"), 0, 20, 0, 11);
  write_tile(d.file("b.tif"), 20, 37, 0, 11);
  write_tile(d.file("c.tif"), 0, 20, 11, 29);  // south-east 17 x 18 missing
  const auto hf = ig::terrain::load_dem(d.path.string());
  EXPECT_EQ(hf.width, 37);
  EXPECT_EQ(hf.height, 29);
  EXPECT_EQ(hf.nodata_count, 17 * 18);
  for (float h : hf.heights) EXPECT_TRUE(std::isfinite(h));
}

TEST(DemMosaic, BadFoldersNameTheFileAndTheReason) {
  TempDir d("bad");
  auto message = [&] {
    try {
      ig::terrain::load_dem(d.path.string());
    } catch (const ig::terrain::DemError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message().find("no DEM tiles in the folder"), std::string::npos) << message();
  std::ofstream(d.file("x.tif")) << "not a tiff";
  EXPECT_NE(message().find("x.tif: tile cannot be read: not a recognised raster format"), std::string::npos)
      << message();
  fs::remove(d.file("x.tif"));
  GDALAllRegister();
  GDALDatasetH two = GDALCreate(GDALGetDriverByName("GTiff"), d.file("two.tif").c_str(), 4, 4, 2, GDT_Float32, nullptr);
  double gt[6] = {0, 1, 0, 0, 0, -1};
  GDALSetGeoTransform(two, gt);
  GDALClose(two);
  EXPECT_NE(message().find("two.tif: tile has 2 raster bands"), std::string::npos) << message();
}

}  // namespace
