// DEM loading of bad input: missing, empty, truncated, absurd or not a
// raster at all. Every one must fail with a one-line DemError naming the
// file, never crash and never yield a partial grid.
#include "terrain/dem_loader.h"

#include <gtest/gtest.h>

#include "terrain/test/dem_loader_test_support.h"

namespace {

using namespace dem_test;

// -------------------------------------------------------- bad files ---

TEST_F(DemLoaderTest, MissingEmptyAndFolders) {
  expect_dem_error(path("nope.tif"), "no such file");
  expect_dem_error(write_file("empty.tif", ""), "empty file (0 bytes)");
  expect_dem_error(write_file("empty.png", ""), "empty file (0 bytes)");
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
  expect_dem_error(write_file("random.tif", noise), "not a recognised raster format");
  expect_dem_error(write_file("notes.png", "this is a text file, not a PNG\n"), "not a recognised raster format");
  expect_dem_error(write_file("notes.dem", "hello\nworld\n"), "not a recognised raster format");
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

// The first half of the file `full` written as `file`: loading that throws a
// DemError naming it (`format` names the kind of file in the failure).
void expect_half_copy_refused(const std::string& full, const std::string& file, const std::string& format) {
  const std::string bytes = read_bytes(full);
  write_bytes(file, bytes.substr(0, bytes.size() / 2));
  try {
    (void)load_dem(file);
    ADD_FAILURE() << "truncated " << format << " loaded";
  } catch (const DemError& e) {
    EXPECT_NE(std::string(e.what()).find(file + ": "), std::string::npos) << e.what();
  }
}

TEST_F(DemLoaderTest, TruncatedGeoTiff) {
  const int n = 256;
  for (const bool deflate : {false, true}) {
    RasterSpec s{n, n, GDT_Float32, {}, std::array<double, 6>{0, 1, 0, 0, 0, -1}, 32630, {}};
    for (int k = 0; k < n * n; ++k) s.values.push_back(std::sin(k * 0.01) * 1000.0);
    const std::string full = path("full.tif");
    write_raster(full, s, deflate ? std::vector<std::string>{"COMPRESS=DEFLATE"}
                                  : std::vector<std::string>{});
    expect_half_copy_refused(full, path(deflate ? "cut_deflate.tif" : "cut.tif"), "GeoTIFF");
  }
}

TEST_F(DemLoaderTest, TruncatedPng) {
  const int n = 300;
  std::vector<std::uint16_t> px(std::size_t(n) * n);
  for (std::size_t k = 0; k < px.size(); ++k) px[k] = std::uint16_t(k * 2654435761u >> 16);
  const std::string full = path("full.png");
  write_image(full, n, n, 1, OIIO::TypeDesc::UINT16, px);
  expect_half_copy_refused(full, path("cut.png"), "PNG");
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

}  // namespace
