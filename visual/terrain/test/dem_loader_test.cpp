// DEM loading: every format the loader supports, written at test time into a
// temporary directory (GDAL for rasters, OpenImageIO for PNGs, by hand for
// .hgt and .asc). The bad files that must fail cleanly are
// dem_loader_bad_files_test.cpp, the real DEMs dem_loader_real_test.cpp.
#include "terrain/dem_loader.h"

#include <gtest/gtest.h>

#include "terrain/test/dem_loader_test_support.h"

namespace {

using namespace dem_test;

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

}  // namespace
