// DEM loading: every format the loader supports, written at test time into a
// temporary directory (GDAL for rasters, OpenImageIO for PNGs, by hand for
// .hgt and .asc), plus the bad files that must fail cleanly. The real DEMs in
// $IG_DEM_DIR (see shared/data/dem/README.md) are checked when it is set.
// Long because every input format and every bad file has its own case.

#include <gdal.h>
#include <cpl_conv.h>
#include <cpl_error.h>
#include <ogr_srs_api.h>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "terrain/dem_loader.h"

namespace fs = std::filesystem;
using ig::terrain::DemError;
using ig::terrain::DemLoadOptions;
using ig::terrain::Heightfield;
using ig::terrain::load_dem;

namespace {

// ------------------------------------------------------------ helpers ---

class DemLoaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    GDALAllRegister();
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("ig_dem_test_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

std::string srs_wkt(int epsg) {
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  EXPECT_EQ(OSRImportFromEPSG(srs, epsg), OGRERR_NONE);
  char* wkt = nullptr;
  OSRExportToWkt(srs, &wkt);
  std::string out = wkt ? wkt : "";
  CPLFree(wkt);
  OSRDestroySpatialReference(srs);
  return out;
}

struct RasterSpec {
  int w = 0, h = 0;
  GDALDataType type = GDT_Int16;
  std::vector<double> values;  // file order: row 0 = north
  std::optional<std::array<double, 6>> gt;
  int epsg = 0;
  std::optional<double> nodata;
};

// Writes a single-band GeoTIFF with GDAL.
void write_raster(const std::string& path, const RasterSpec& s,
                  const std::vector<std::string>& create_options = {}) {
  const char* driver = "GTiff";
  GDALDriverH drv = GDALGetDriverByName(driver);
  ASSERT_NE(drv, nullptr) << driver;
  std::vector<char*> opts;
  for (const auto& o : create_options) opts.push_back(const_cast<char*>(o.c_str()));
  opts.push_back(nullptr);
  GDALDatasetH ds = GDALCreate(drv, path.c_str(), s.w, s.h, 1, s.type, opts.data());
  ASSERT_NE(ds, nullptr) << CPLGetLastErrorMsg();
  if (s.gt) {
    std::array<double, 6> gt = *s.gt;
    GDALSetGeoTransform(ds, gt.data());
  }
  if (s.epsg) GDALSetProjection(ds, srs_wkt(s.epsg).c_str());
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  if (s.nodata) GDALSetRasterNoDataValue(band, *s.nodata);
  std::vector<double> v = s.values;
  ASSERT_EQ(v.size(), std::size_t(s.w) * s.h);
  ASSERT_EQ(GDALRasterIO(band, GF_Write, 0, 0, s.w, s.h, v.data(), s.w, s.h, GDT_Float64, 0, 0),
            CE_None);
  GDALClose(ds);
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream f(path, std::ios::binary);
  f.write(bytes.data(), std::streamsize(bytes.size()));
}

std::string read_bytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

template <typename T>
void write_image(const std::string& path, int w, int h, int nch, OIIO::TypeDesc type,
                 const std::vector<T>& pixels) {
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out) << OIIO::geterror();
  ASSERT_TRUE(out->open(path, OIIO::ImageSpec(w, h, nch, type))) << out->geterror();
  ASSERT_TRUE(out->write_image(type, pixels.data())) << out->geterror();
  ASSERT_TRUE(out->close());
}

// The test's own ellipsoid formula (independent of the loader's).
double meridian_m_per_deg(double lat_deg) {
  const double a = 6378137.0, f = 1.0 / 298.257223563, e2 = f * (2 - f);
  const double s = std::sin(lat_deg * std::numbers::pi / 180);
  return a * (1 - e2) / std::pow(1 - e2 * s * s, 1.5) * std::numbers::pi / 180;
}

void expect_no_nan(const Heightfield& hf) {
  ASSERT_EQ(hf.heights.size(), std::size_t(hf.width) * hf.height);
  for (float v : hf.heights) ASSERT_TRUE(std::isfinite(v));
}

// The load must throw a DemError whose message names the file and contains
// `reason`; nothing else may escape.
void expect_dem_error(const std::string& file, const std::string& reason,
                      const DemLoadOptions& opts = {}) {
  try {
    (void)load_dem(file, opts);
    ADD_FAILURE() << "no error for " << file;
  } catch (const DemError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(file + ": "), std::string::npos) << msg;
    EXPECT_NE(msg.find(reason), std::string::npos) << "expected '" << reason << "' in: " << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "message must be one line: " << msg;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong exception type for " << file << ": " << e.what();
  }
}

// ---------------------------------------------------------- formats ---

TEST_F(DemLoaderTest, GeoTiffInt16GeographicFlipsRowsAndDerivesSpacing) {
  // 3 arc-second grid centred on 37 deg N.
  const int w = 40, h = 30;
  const double px = 1.0 / 1200.0;
  const double top = 37.0 + (h / 2) * px, left = -120.0;
  RasterSpec s{w, h, GDT_Int16, {}, std::array<double, 6>{left, px, 0, top, 0, -px}, 4326, {}};
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) s.values.push_back(-500 + r * 100 + c);
  const std::string file = path("geo_int16.tif");
  write_raster(file, s);

  const Heightfield hf = load_dem(file);
  ASSERT_EQ(hf.width, w);
  ASSERT_EQ(hf.height, h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) ASSERT_EQ(hf.at(i, j), float(-500 + (h - 1 - j) * 100 + i));
  EXPECT_EQ(hf.source, file);
  EXPECT_EQ(hf.nodata_count, 0);
  EXPECT_EQ(hf.min_m, -500.0f);
  EXPECT_EQ(hf.max_m, float(-500 + (h - 1) * 100 + w - 1));

  // N-S: 3 arc-seconds of meridian arc at 37 deg N on WGS84 is 92.48 m (the
  // README's 92.6 m is the spherical-Earth mean); E-W: about cos(37 deg) of it.
  EXPECT_NEAR(hf.spacing_y_m, meridian_m_per_deg(37.0) / 1200.0, 1e-6);
  EXPECT_GT(hf.spacing_y_m, 92.4);
  EXPECT_LT(hf.spacing_y_m, 92.7);
  const double expect_x = std::cos(37.0 * std::numbers::pi / 180) * hf.spacing_y_m;
  EXPECT_NEAR(hf.spacing_x_m / expect_x, 1.0, 0.005);

  ASSERT_TRUE(hf.georef.has_value());
  EXPECT_EQ(hf.georef->crs_name, "EPSG:4326");
  EXPECT_TRUE(hf.georef->geographic);
  EXPECT_FALSE(hf.georef->crs_wkt.empty());
  const auto& g = hf.georef->grid_to_crs;
  EXPECT_NEAR(g[0], left + 0.5 * px, 1e-12);         // west sample centre
  EXPECT_NEAR(g[3], top - (h - 0.5) * px, 1e-12);    // south sample centre
  EXPECT_NEAR(g[1], px, 1e-15);
  EXPECT_NEAR(g[5], px, 1e-15);                      // j grows northward
  EXPECT_NEAR(g[3] + (h - 1) * g[5], top - 0.5 * px, 1e-12);
}

TEST_F(DemLoaderTest, GeoTiffUInt16ProjectedUtm) {
  const int w = 17, h = 9;
  RasterSpec s{w, h, GDT_UInt16, {}, std::array<double, 6>{500000, 30, 0, 4100000, 0, -30},
               32633, {}};
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) s.values.push_back(40000 + r * 1000 + c);  // > int16 max
  const std::string file = path("utm_u16.tif");
  write_raster(file, s);

  const Heightfield hf = load_dem(file);
  EXPECT_EQ(hf.at(0, h - 1), 40000.0f);                    // file's first sample: NW
  EXPECT_EQ(hf.at(w - 1, 0), float(40000 + (h - 1) * 1000 + w - 1));
  EXPECT_DOUBLE_EQ(hf.spacing_x_m, 30.0);
  EXPECT_DOUBLE_EQ(hf.spacing_y_m, 30.0);
  ASSERT_TRUE(hf.georef);
  EXPECT_EQ(hf.georef->crs_name, "EPSG:32633");
  EXPECT_FALSE(hf.georef->geographic);
  EXPECT_DOUBLE_EQ(hf.georef->grid_to_crs[0], 500015.0);
  EXPECT_DOUBLE_EQ(hf.georef->grid_to_crs[3], 4100000.0 - 30.0 * h + 15.0);
}

TEST_F(DemLoaderTest, GeoTiffFloat32NodataIsFilledAndCounted) {
  // A tilted plane, so filled values can be checked against it.
  const int w = 32, h = 24;
  auto plane = [](int c, int r) { return 1000.0 + 2.5 * c - 1.5 * r; };
  RasterSpec s{w, h, GDT_Float32, {}, std::array<double, 6>{300000, 10, 0, 5000000, 0, -10},
               32630, -9999.0};
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) s.values.push_back(plane(c, r));
  auto set = [&](int c, int r, double v) { s.values[std::size_t(r) * w + c] = v; };
  int voids = 0;
  set(5, 5, -9999.0), ++voids;                        // lone nodata sample
  set(0, 0, -9999.0), ++voids;                        // corner
  set(20, 10, std::nan("")), ++voids;                 // NaN
  set(21, 10, HUGE_VAL), ++voids;                     // +Inf
  set(22, 10, -32768.0), ++voids;                     // SRTM void value
  for (int r = 14; r < 20; ++r)                       // 6x6 hole
    for (int c = 8; c < 14; ++c) set(c, r, -9999.0), ++voids;
  const std::string file = path("f32_nodata.tif");
  write_raster(file, s);

  const Heightfield hf = load_dem(file);
  expect_no_nan(hf);
  EXPECT_EQ(hf.nodata_count, voids);
  auto at_file = [&](int c, int r) { return hf.at(c, h - 1 - r); };
  // The lone void: GDAL's fill takes the nearest valid sample in each
  // quadrant, N (+1.5 m from the plane at the void), S (-1.5), E (+2.5) at
  // 1 sample and SE (+1) at sqrt 2, weighted by 1 / distance; each of the
  // two smoothing passes then averages it with its 8 valid neighbours, whose
  // mean is the plane there, so 1/81 of the interpolation's offset is left.
  const double r2 = std::sqrt(2.0);
  const double offset = (1.5 - 1.5 + 2.5 + 1.0 / r2) / (3.0 + 1.0 / r2);
  EXPECT_NEAR(at_file(5, 5), plane(5, 5) + offset / 81.0, 1e-3);
  // (20..22, 10) are adjacent voids: filled from one-sided neighbours, so only
  // close to the plane (it rises 2.5 m per column).
  EXPECT_NEAR(at_file(20, 10), plane(20, 10), 2.5);
  EXPECT_NEAR(at_file(22, 10), plane(22, 10), 2.5);
  for (int r = 14; r < 20; ++r)
    for (int c = 8; c < 14; ++c) {
      EXPECT_GE(at_file(c, r), plane(7, 20) - 1e-3);  // within the hole's rim range
      EXPECT_LE(at_file(c, r), plane(14, 13) + 1e-3);
    }
  EXPECT_GE(hf.min_m, float(plane(0, h - 1)) - 1e-3f);
  EXPECT_LE(hf.max_m, float(plane(w - 1, 0)) + 1e-3f);
  EXPECT_EQ(hf.georef->crs_name, "EPSG:32630");
}

TEST_F(DemLoaderTest, AllNodataIsAnError) {
  RasterSpec s{4, 4, GDT_Int16, std::vector<double>(16, -32768.0),
               std::array<double, 6>{0, 1, 0, 0, 0, -1}, 0, -32768.0};
  const std::string file = path("all_void.tif");
  write_raster(file, s);
  expect_dem_error(file, "all 16 samples are nodata");
}

TEST_F(DemLoaderTest, SpacingOverride) {
  RasterSpec s{3, 3, GDT_Float32, std::vector<double>(9, 7.0),
               std::array<double, 6>{0, 25, 0, 0, 0, -25}, 32630, {}};
  const std::string file = path("override.tif");
  write_raster(file, s);
  DemLoadOptions o;
  o.spacing_m = 12.5;
  const Heightfield hf = load_dem(file, o);
  EXPECT_EQ(hf.spacing_x_m, 12.5);
  EXPECT_EQ(hf.spacing_y_m, 12.5);
  EXPECT_TRUE(hf.georef);
}

TEST_F(DemLoaderTest, EsriAsciiGrid) {
  const std::string file = path("tiny.asc");
  write_bytes(file,
              "ncols 4\nnrows 3\nxllcorner 1000\nyllcorner 2000\ncellsize 10\n"
              "NODATA_value -9999\n"
              "1 2 3 4\n"
              "5 -9999 7 8\n"
              "9 10 11 12\n");
  const Heightfield hf = load_dem(file);
  ASSERT_EQ(hf.width, 4);
  ASSERT_EQ(hf.height, 3);
  EXPECT_EQ(hf.at(0, 2), 1.0f);  // first text row is north
  EXPECT_EQ(hf.at(3, 0), 12.0f);
  EXPECT_EQ(hf.nodata_count, 1);
  // GDAL's fill: the nearest valid sample in each quadrant, 2 (north) 10
  // (south) 7 (east) at 1 sample and 11 (south-east) at sqrt 2, weighted by
  // 1 / distance; then two smoothing passes, each the mean of the 3x3 block
  // (its 8 neighbours sum to 48).
  const double r2 = std::sqrt(2.0);
  const double interpolated = (2.0 + 10.0 + 7.0 + 11.0 / r2) / (3.0 + 1.0 / r2);
  const double smoothed = (48.0 + (48.0 + interpolated) / 9.0) / 9.0;
  EXPECT_NEAR(hf.at(1, 1), smoothed, 1e-5);
  EXPECT_EQ(hf.spacing_x_m, 10.0);  // no .prj: cell size taken as metres
  EXPECT_EQ(hf.spacing_y_m, 10.0);
  ASSERT_TRUE(hf.georef);
  EXPECT_TRUE(hf.georef->crs_name.empty());
  EXPECT_DOUBLE_EQ(hf.georef->grid_to_crs[0], 1005.0);
  EXPECT_DOUBLE_EQ(hf.georef->grid_to_crs[3], 2005.0);
}

TEST_F(DemLoaderTest, UsgsDemWrittenByGdal) {
  // GDAL's USGSDEM driver can CreateCopy a geographic (WGS84) grid.
  const int n = 121;
  const double px = 1.0 / 1200.0;
  RasterSpec s{n, n, GDT_Int16, {},
               std::array<double, 6>{-72.0 - px / 2, px, 0, 45.0 + px / 2, 0, -px}, 4326, {}};
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) s.values.push_back(200 + 3 * r + c);
  const std::string src = path("usgs_src.tif");
  write_raster(src, s);
  GDALDatasetH in = GDALOpen(src.c_str(), GA_ReadOnly);
  ASSERT_NE(in, nullptr);
  const std::string file = path("tile.dem");
  CPLPushErrorHandler(CPLQuietErrorHandler);
  GDALDatasetH out =
      GDALCreateCopy(GDALGetDriverByName("USGSDEM"), file.c_str(), in, FALSE, nullptr,
                     nullptr, nullptr);
  CPLPopErrorHandler();
  GDALClose(in);
  if (!out) GTEST_SKIP() << "GDAL could not write a USGS DEM: " << CPLGetLastErrorMsg();
  GDALClose(out);

  const Heightfield hf = load_dem(file);
  ASSERT_EQ(hf.width, n);
  ASSERT_EQ(hf.height, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) ASSERT_EQ(hf.at(i, j), float(200 + 3 * (n - 1 - j) + i));
  ASSERT_TRUE(hf.georef);
  EXPECT_TRUE(hf.georef->geographic);
  EXPECT_NEAR(hf.spacing_y_m, meridian_m_per_deg(44.95) / 1200.0, 0.01);
  EXPECT_NEAR(hf.georef->grid_to_crs[0], -72.0, 1e-6);
  EXPECT_NEAR(hf.georef->grid_to_crs[3], 45.0 - (n - 1) * px, 1e-6);
}

// Raw SRTM tile, written byte by byte: 1201x1201 big-endian int16, north first.
std::string make_hgt(const std::function<int(int, int)>& value) {
  std::string bytes(2u * 1201 * 1201, '\0');
  for (int r = 0; r < 1201; ++r)
    for (int c = 0; c < 1201; ++c) {
      const auto v = static_cast<std::uint16_t>(static_cast<std::int16_t>(value(c, r)));
      const std::size_t k = 2 * (std::size_t(r) * 1201 + c);
      bytes[k] = char(v >> 8);
      bytes[k + 1] = char(v & 0xff);
    }
  return bytes;
}

TEST_F(DemLoaderTest, SrtmHgtRowFlipVoidAndGeoref) {
  auto value = [](int c, int r) {
    if (c == 600 && r == 300) return -32768;  // one void
    return (r * 7 + c * 3) % 3000 - 100;
  };
  const std::string file = path("N44W072.hgt");
  write_bytes(file, make_hgt(value));

  const Heightfield hf = load_dem(file);
  ASSERT_EQ(hf.width, 1201);
  ASSERT_EQ(hf.height, 1201);
  // The file's first row is the north edge = our last row.
  for (int c = 0; c < 1201; c += 97) {
    EXPECT_EQ(hf.at(c, 1200), float(value(c, 0)));
    EXPECT_EQ(hf.at(c, 0), float(value(c, 1200)));
    EXPECT_EQ(hf.at(c, 1200 - 77), float(value(c, 77)));
  }
  EXPECT_EQ(hf.nodata_count, 1);
  expect_no_nan(hf);
  EXPECT_GT(hf.at(600, 1200 - 300), -200.0f);
  ASSERT_TRUE(hf.georef);
  EXPECT_EQ(hf.georef->crs_name, "EPSG:4326");
  EXPECT_NEAR(hf.georef->grid_to_crs[0], -72.0, 1e-9);  // SW sample centre is 44N 72W
  EXPECT_NEAR(hf.georef->grid_to_crs[3], 44.0, 1e-9);
  EXPECT_NEAR(hf.spacing_y_m, meridian_m_per_deg(44.5) / 1200.0, 1e-6);
  EXPECT_NEAR(hf.spacing_x_m / (std::cos(44.5 * std::numbers::pi / 180) * hf.spacing_y_m), 1.0,
              0.005);
}

TEST_F(DemLoaderTest, Png16ScaleOffsetExact) {
  const int w = 5, h = 3;
  std::vector<std::uint16_t> px = {0, 1, 2, 3, 65535, 100, 200, 300, 400, 500,
                                   1000, 2000, 3000, 40000, 65534};
  const std::string file = path("dem16.png");
  write_image(file, w, h, 1, OIIO::TypeDesc::UINT16, px);

  DemLoadOptions o;
  o.scale = 0.5;
  o.offset = -100.0;
  const Heightfield hf = load_dem(file, o);  // auto -> png16
  ASSERT_EQ(hf.width, w);
  ASSERT_EQ(hf.height, h);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      EXPECT_EQ(hf.at(c, h - 1 - r), float(px[std::size_t(r) * w + c] * 0.5 - 100.0));
  EXPECT_FALSE(hf.georef);
  EXPECT_EQ(hf.spacing_x_m, 1.0);
  EXPECT_EQ(hf.max_m, float(65535 * 0.5 - 100));

  o.spacing_m = 30.0;
  o.encoding = "png16";
  const Heightfield hf30 = load_dem(file, o);
  EXPECT_EQ(hf30.spacing_x_m, 30.0);
  EXPECT_EQ(hf30.spacing_y_m, 30.0);
  EXPECT_EQ(hf30.heights, hf.heights);
}

TEST_F(DemLoaderTest, TerrainRgbExact) {
  const int w = 4, h = 2;
  // Codes covering -10000 m, 0 m (100000), sea-level +-, and big heights.
  const std::array<std::uint32_t, 8> codes = {0, 100000, 99999, 100001,
                                              137512, 237510, 1234567, 16777215};
  for (int nch : {3, 4}) {
    std::vector<std::uint8_t> px;
    for (std::uint32_t code : codes) {
      px.push_back(std::uint8_t(code >> 16));
      px.push_back(std::uint8_t(code >> 8));
      px.push_back(std::uint8_t(code));
      if (nch == 4) px.push_back(255);
    }
    const std::string file = path("rgb" + std::to_string(nch) + ".png");
    write_image(file, w, h, nch, OIIO::TypeDesc::UINT8, px);
    for (const char* enc : {"auto", "terrain-rgb"}) {
      DemLoadOptions o;
      o.encoding = enc;
      const Heightfield hf = load_dem(file, o);
      for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c)
          EXPECT_EQ(hf.at(c, h - 1 - r), float(-10000.0 + codes[std::size_t(r) * w + c] * 0.1))
              << nch << " channels, " << enc;
      EXPECT_EQ(hf.at(1, 1), 0.0f);
    }
  }
}

TEST_F(DemLoaderTest, EightBitGrayPngIsRejectedWithTheSupportedEncodings) {
  const std::string file = path("gray8.png");
  write_image(file, 4, 4, 1, OIIO::TypeDesc::UINT8, std::vector<std::uint8_t>(16, 9));
  expect_dem_error(file, "8-bit grayscale");
  expect_dem_error(file, "png16");
  expect_dem_error(file, "terrain-rgb");
  DemLoadOptions o;
  o.encoding = "png16";
  expect_dem_error(file, "png16 needs a 16-bit", o);
}

TEST_F(DemLoaderTest, InfoJsonParses) {
  RasterSpec s{3, 2, GDT_Float32, {1, 2, 3, 4, 5, 6},
               std::array<double, 6>{-10.0, 0.5, 0, 50.0, 0, -0.5}, 4326, {}};
  const std::string file = path("json \"quoted\".tif");
  write_raster(file, s);
  const Heightfield hf = load_dem(file);
  const auto j = nlohmann::json::parse(ig::terrain::dem_info_json(hf));
  EXPECT_EQ(j["width"], 3);
  EXPECT_EQ(j["height"], 2);
  EXPECT_EQ(j["min_m"], 1.0);
  EXPECT_EQ(j["max_m"], 6.0);
  EXPECT_DOUBLE_EQ(j["mean_m"].get<double>(), 3.5);
  EXPECT_EQ(j["nodata_count"], 0);
  EXPECT_EQ(j["crs"], "EPSG:4326");
  EXPECT_EQ(j["geographic"], true);
  EXPECT_EQ(j["source"], file);
  EXPECT_DOUBLE_EQ(j["corners"]["nw"][0].get<double>(), -9.75);
  EXPECT_DOUBLE_EQ(j["corners"]["nw"][1].get<double>(), 49.75);
  EXPECT_DOUBLE_EQ(j["corners"]["se"][0].get<double>(), -8.75);
  EXPECT_DOUBLE_EQ(j["corners"]["se"][1].get<double>(), 49.25);
  EXPECT_DOUBLE_EQ(j["bounds"]["west"].get<double>(), -10.0);
  EXPECT_DOUBLE_EQ(j["bounds"]["north"].get<double>(), 50.0);
  EXPECT_DOUBLE_EQ(j["bounds"]["east"].get<double>(), -8.5);
  EXPECT_DOUBLE_EQ(j["bounds"]["south"].get<double>(), 49.0);

  Heightfield plain;
  plain.width = plain.height = 2;
  plain.heights = {1, 2, 3, 4};
  plain.finalize_stats();
  const auto p = nlohmann::json::parse(ig::terrain::dem_info_json(plain));
  EXPECT_TRUE(p["crs"].is_null());
  EXPECT_EQ(p["geographic"], false);
  EXPECT_FALSE(p.contains("corners"));
}

TEST(MetresPerAngle, KnownValues) {
  // WGS84: 110 574 m per degree of latitude at the equator, 111 694 m at the
  // poles; 111 320 m per degree of longitude at the equator.
  const auto eq = ig::terrain::metres_per_angle(0.0);
  EXPECT_NEAR(eq.north, 110574.3, 0.5);
  EXPECT_NEAR(eq.east, 111319.5, 0.5);
  EXPECT_NEAR(ig::terrain::metres_per_angle(90.0).north, 111693.9, 0.5);
  EXPECT_NEAR(ig::terrain::metres_per_angle(45.0).north, 111132.1, 0.5);
  EXPECT_NEAR(ig::terrain::metres_per_angle(90.0).east, 0.0, 1e-6);
  const auto sphere = ig::terrain::metres_per_angle(60.0, 6371000.0, 0.0);
  EXPECT_NEAR(sphere.north, 6371000.0 * std::numbers::pi / 180, 1e-6);
  EXPECT_NEAR(sphere.east, 0.5 * sphere.north, 1e-6);
}

// -------------------------------------------------------- bad files ---

TEST_F(DemLoaderTest, MissingEmptyAndFolders) {
  expect_dem_error(path("nope.tif"), "no such file");
  const std::string empty = path("empty.tif");
  write_bytes(empty, "");
  expect_dem_error(empty, "empty file (0 bytes)");
  const std::string empty_png = path("empty.png");
  write_bytes(empty_png, "");
  expect_dem_error(empty_png, "empty file (0 bytes)");
  // A folder is read as a mosaic of its tiles (dem_mosaic_test.cpp): an
  // empty one has none, this one has an unreadable tile.
  fs::create_directories(path("adir.tif"));
  expect_dem_error(path("adir.tif"), "no DEM tiles in the folder");
  const std::string message = [&] {
    try {
      ig::terrain::load_dem(dir_.string());
    } catch (const ig::terrain::DemError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  }();
  EXPECT_NE(message.find("empty.tif: tile cannot be read"), std::string::npos) << message;
}

TEST_F(DemLoaderTest, NotARaster) {
  std::string noise(4096, '\0');
  std::uint32_t x = 12345;
  for (char& c : noise) {
    x = x * 1664525u + 1013904223u;
    c = char(x >> 24);
  }
  const std::string random_tif = path("random.tif");
  write_bytes(random_tif, noise);
  expect_dem_error(random_tif, "not a recognised raster format");

  const std::string text_png = path("notes.png");
  write_bytes(text_png, "this is a text file, not a PNG\n");
  expect_dem_error(text_png, "not a recognised raster format");

  const std::string text_dem = path("notes.dem");
  write_bytes(text_dem, "hello\nworld\n");
  expect_dem_error(text_dem, "not a recognised raster format");
}

TEST_F(DemLoaderTest, TruncatedHgt) {
  const std::string file = path("N44W072.hgt");
  std::string bytes = make_hgt([](int c, int r) { return 100; });
  write_bytes(file, bytes.substr(0, bytes.size() / 2));
  expect_dem_error(file, "truncated or wrong-size SRTM .hgt: 1442401 bytes, expected 2884802 "
                         "(1201x1201) or 25934402 (3601x3601)");
  write_bytes(file, "short");
  expect_dem_error(file, "truncated or wrong-size SRTM .hgt: 5 bytes");
}

TEST_F(DemLoaderTest, TruncatedGeoTiff) {
  const int n = 256;
  for (const bool deflate : {false, true}) {
    RasterSpec s{n, n, GDT_Float32, {}, std::array<double, 6>{0, 1, 0, 0, 0, -1}, 32630, {}};
    for (int k = 0; k < n * n; ++k) s.values.push_back(std::sin(k * 0.01) * 1000.0);
    const std::string full = path("full.tif");
    write_raster(full, s, deflate ? std::vector<std::string>{"COMPRESS=DEFLATE"}
                                  : std::vector<std::string>{});
    const std::string bytes = read_bytes(full);
    const std::string file = path(deflate ? "cut_deflate.tif" : "cut.tif");
    write_bytes(file, bytes.substr(0, bytes.size() / 2));
    try {
      (void)load_dem(file);
      ADD_FAILURE() << "truncated GeoTIFF loaded";
    } catch (const DemError& e) {
      EXPECT_NE(std::string(e.what()).find(file + ": "), std::string::npos) << e.what();
    }
  }
}

TEST_F(DemLoaderTest, TruncatedPng) {
  const int n = 300;
  std::vector<std::uint16_t> px(std::size_t(n) * n);
  for (std::size_t k = 0; k < px.size(); ++k) px[k] = std::uint16_t(k * 2654435761u >> 16);
  const std::string full = path("full.png");
  write_image(full, n, n, 1, OIIO::TypeDesc::UINT16, px);
  const std::string bytes = read_bytes(full);
  const std::string file = path("cut.png");
  write_bytes(file, bytes.substr(0, bytes.size() / 2));
  try {
    (void)load_dem(file);
    ADD_FAILURE() << "truncated PNG loaded";
  } catch (const DemError& e) {
    EXPECT_NE(std::string(e.what()).find(file + ": "), std::string::npos) << e.what();
  }
}

TEST_F(DemLoaderTest, AbsurdSizes) {
  const std::string huge = path("huge.asc");
  write_bytes(huge,
              "ncols 100000\nnrows 100000\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n");
  expect_dem_error(huge, "100000x100000");
  expect_dem_error(huge, "too large");

  const std::string tiny = path("tiny.asc");
  write_bytes(tiny, "ncols 1\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1\n5\n");
  expect_dem_error(tiny, "1x1");
  expect_dem_error(tiny, "too small");
}

TEST_F(DemLoaderTest, BadOptions) {
  RasterSpec s{2, 2, GDT_Int16, {1, 2, 3, 4}, {}, 0, {}};
  const std::string file = path("small.tif");
  write_raster(file, s);
  DemLoadOptions o;
  o.encoding = "jpeg";
  expect_dem_error(file, "unknown encoding 'jpeg'", o);
  DemLoadOptions t;
  t.encoding = "terrain-rgb";  // a 1-band int16 TIFF is not terrain-RGB
  expect_dem_error(file, "terrain-rgb needs an 8-bit RGB", t);
  // Without georeferencing the spacing is 1 m and there is no georef.
  const Heightfield hf = load_dem(file);
  EXPECT_FALSE(hf.georef);
  EXPECT_EQ(hf.spacing_x_m, 1.0);
}

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
