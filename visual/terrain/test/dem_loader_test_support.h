#pragma once
// Shared fixture of the DEM loader tests (dem_loader_test.cpp,
// dem_loader_bad_files_test.cpp, dem_loader_real_test.cpp; header only): a
// temporary directory per test, writers for GeoTIFFs (GDAL), PNGs
// (OpenImageIO) and raw bytes, and the DemError check.

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

namespace dem_test {

namespace fs = std::filesystem;
using ig::terrain::DemError;
using ig::terrain::DemLoadOptions;
using ig::terrain::Heightfield;
using ig::terrain::load_dem;

inline void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream f(path, std::ios::binary);
  f.write(bytes.data(), std::streamsize(bytes.size()));
}

inline std::string read_bytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

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
  // `bytes` written as the file `name` in the test's directory: its path.
  std::string write_file(const std::string& name, const std::string& bytes) const {
    const std::string p = path(name);
    write_bytes(p, bytes);
    return p;
  }

  fs::path dir_;
};

inline std::string srs_wkt(int epsg) {
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
inline void write_raster(const std::string& path, const RasterSpec& s,
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

template <typename T>
inline void write_image(const std::string& path, int w, int h, int nch, OIIO::TypeDesc type,
                 const std::vector<T>& pixels) {
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out) << OIIO::geterror();
  ASSERT_TRUE(out->open(path, OIIO::ImageSpec(w, h, nch, type))) << out->geterror();
  ASSERT_TRUE(out->write_image(type, pixels.data())) << out->geterror();
  ASSERT_TRUE(out->close());
}

// The test's own ellipsoid formula (independent of the loader's).
inline double meridian_m_per_deg(double lat_deg) {
  const double a = 6378137.0, f = 1.0 / 298.257223563, e2 = f * (2 - f);
  const double s = std::sin(lat_deg * std::numbers::pi / 180);
  return a * (1 - e2) / std::pow(1 - e2 * s * s, 1.5) * std::numbers::pi / 180;
}

inline void expect_no_nan(const Heightfield& hf) {
  ASSERT_EQ(hf.heights.size(), std::size_t(hf.width) * hf.height);
  for (float v : hf.heights) ASSERT_TRUE(std::isfinite(v));
}

// The load must throw a DemError whose message names the file and contains
// `reason`; nothing else may escape.
inline void expect_dem_error(const std::string& file, const std::string& reason,
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

// Raw SRTM tile, written byte by byte: 1201x1201 big-endian int16, north first.
inline std::string make_hgt(const std::function<int(int, int)>& value) {
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

}  // namespace dem_test
