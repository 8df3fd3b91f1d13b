// The user's water data: polygons burned into the cells gdal_rasterize burns,
// a raster mask warped onto the grid, levels from the DEM or an attribute,
// the heights made level, and every bad file named with its reason.
#include "water/water_file.h"

#include <cpl_conv.h>
#include <gdal.h>
#include <gtest/gtest.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "terrain/test/temp_dir_fixture.h"
#include "terrain/dem_loader.h"
#include "terrain/georef.h"
#include "water/test/water_test_terrain.h"
#include "water/water_levels.h"
#include "water/water_setup.h"

namespace ig::water {
namespace {

using test::kLakeLevel;
using test::make_water_test_terrain;
using test::TestFeatures;

class WaterFile : public terrain::test::TempDirTest {
 protected:
  WaterFile() : TempDirTest("ig_water_file_") {}

  // Lon, lat of sample (i, j) of hf (fractions allowed).
  static std::pair<double, double> lon_lat(const terrain::Heightfield& hf, double i, double j) {
    const auto& g = hf.georef->grid_to_crs;
    return {g[0] + i * g[1] + j * g[2], g[3] + i * g[4] + j * g[5]};
  }
  // GeoJSON positions of sample positions: "[[lon,lat],...]", closed into a ring or not.
  static std::string positions(const terrain::Heightfield& hf, const std::vector<std::pair<double, double>>& samples,
                               bool closed) {
    std::ostringstream o;
    o.precision(12);
    o << "[";
    for (std::size_t k = 0; k < samples.size() + (closed ? 1 : 0); ++k) {
      const auto [lon, lat] = lon_lat(hf, samples[k % samples.size()].first, samples[k % samples.size()].second);
      o << (k ? "," : "") << "[" << lon << "," << lat << "]";
    }
    o << "]";
    return o.str();
  }
  static std::string ring(const terrain::Heightfield& hf, const std::vector<std::pair<double, double>>& samples) {
    return "[" + positions(hf, samples, true) + "]";
  }
  std::string write(const std::string& name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }
  static std::string feature(const std::string& geometry, const std::string& properties = "{}") {
    return R"({"type":"Feature","properties":)" + properties + R"(,"geometry":)" + geometry + "}";
  }
  static std::string collection(const std::vector<std::string>& features) {
    std::string s = R"({"type":"FeatureCollection","features":[)";
    for (std::size_t k = 0; k < features.size(); ++k) s += (k ? "," : "") + features[k];
    return s + "]}";
  }
  static std::string polygon(const std::string& ring) { return R"({"type":"Polygon","coordinates":)" + ring + "}"; }

  // What gdal_rasterize burns for `vector` on hf's grid, south-up rows.
  std::vector<std::uint8_t> gdal_rasterize(const terrain::Heightfield& hf, const std::string& vector) {
    const auto b = *hf.crs_bounds();
    const std::string out = (dir_ / "burned.tif").string();
    std::ostringstream cmd;
    cmd.precision(17);
    cmd << "gdal_rasterize -q -burn 1 -init 0 -ot Byte -te " << b[0] << " " << b[1] << " " << b[2] << " " << b[3]
        << " -ts " << hf.width << " " << hf.height << " '" << vector << "' '" << out << "'";
    EXPECT_EQ(std::system(cmd.str().c_str()), 0) << cmd.str();
    GDALAllRegister();
    GDALDatasetH ds = GDALOpen(out.c_str(), GA_ReadOnly);
    EXPECT_NE(ds, nullptr);
    std::vector<std::uint8_t> north(std::size_t(hf.width) * hf.height), south(north.size());
    if (!ds) return south;
    EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Read, 0, 0, hf.width, hf.height, north.data(), hf.width,
                           hf.height, GDT_Byte, 0, 0),
              CE_None);
    GDALClose(ds);
    for (int r = 0; r < hf.height; ++r)
      std::copy_n(north.begin() + std::ptrdiff_t(r) * hf.width, hf.width,
                  south.begin() + std::ptrdiff_t(hf.height - 1 - r) * hf.width);
    return south;
  }

  std::string error_of(const terrain::Heightfield& hf, const std::string& path,
                       const std::optional<std::string>& attribute = std::nullopt) {
    try {
      read_water_file(hf, path, attribute);
    } catch (const WaterFileError& e) {
      return e.what();
    }
    ADD_FAILURE() << path << " was read without an error";
    return "";
  }
};

TEST_F(WaterFile, PolygonsBurnTheCellsGdalRasterizeBurns) {
  const terrain::Heightfield hf = make_water_test_terrain();
  const std::vector<std::string> lakes = {
      feature(polygon(ring(hf, {{40.3, 80.2}, {75.7, 78.9}, {83.1, 101.4}, {61.2, 117.6}, {44.8, 104.1}}))),
      feature(polygon(ring(hf, {{120.5, 70.5}, {160.2, 72.0}, {140.1, 99.9}})))};
  const std::string path = write("lakes.geojson", collection(lakes));
  const WaterMap map = read_water_file(hf, path);
  EXPECT_EQ(map.source(), path);
  ASSERT_EQ(map.bodies().size(), 2u);
  for (const WaterBody& b : map.bodies()) EXPECT_EQ(b.kind, WaterKind::Mapped);
  // A line beside them holds no water (gdal_rasterize would burn it).
  std::vector<std::string> with_line = lakes;
  with_line.push_back(feature(R"({"type":"LineString","coordinates":)" + positions(hf, {{10, 20}, {30, 40}}, false) + "}"));
  EXPECT_TRUE(read_water_file(hf, write("with_line.geojson", collection(with_line))) == map);
  const std::vector<std::uint8_t> burned = gdal_rasterize(hf, path);
  std::int64_t water = 0, differ = 0;
  for (int j = 0; j < hf.height; ++j)
    for (int i = 0; i < hf.width; ++i) {
      water += burned[std::size_t(j) * hf.width + i];
      differ += map.is_water(i, j) != (burned[std::size_t(j) * hf.width + i] != 0);
    }
  EXPECT_GT(water, 1000);
  EXPECT_EQ(differ, 0);
  EXPECT_EQ(map.water_samples(), water);
}

TEST_F(WaterFile, LevelsFromTheDemOrAnAttribute) {
  const TestFeatures f;
  terrain::Heightfield hf = make_water_test_terrain(200, 150, f);
  // Inside the flat lake, mostly: its one exact height. Over rough land:
  // the median of its rim. Over the sea's edge: 0 m.
  const std::string lake = ring(hf, {{f.lake_i - 8.0, f.lake_j - 8.0}, {f.lake_i + 13.5, f.lake_j - 8.0},
                                     {f.lake_i + 13.5, f.lake_j + 8.0}, {f.lake_i - 8.0, f.lake_j + 8.0}});
  const std::string land = ring(hf, {{100.2, 70.2}, {130.2, 70.2}, {130.2, 90.2}, {100.2, 90.2}});
  const std::string coast = ring(hf, {{150.2, 2.2}, {190.2, 2.2}, {190.2, 13.2}, {150.2, 13.2}});
  const std::string path = write("three.geojson", collection({feature(polygon(lake), R"({"lvl": 1201.5})"),
                                                              feature(polygon(land), R"({"lvl": 1330})"),
                                                              feature(polygon(coast), R"({"lvl": -2})")}));
  const WaterMap map = read_water_file(hf, path);
  ASSERT_EQ(map.bodies().size(), 3u);
  // Bodies are numbered by their first (southernmost) sample: coast, land, lake.
  EXPECT_EQ(map.bodies()[0].level_m, 0.0f);
  EXPECT_EQ(map.bodies()[2].level_m, kLakeLevel);
  std::vector<float> rim;
  for (int j = 0; j < hf.height; ++j)
    for (int i = 0; i < hf.width; ++i)
      if (map.body_at(i, j) == std::optional<std::uint32_t>(1) &&
          (!map.is_water(i - 1, j) || !map.is_water(i + 1, j) || !map.is_water(i, j - 1) || !map.is_water(i, j + 1)))
        rim.push_back(hf.at(i, j));
  ASSERT_FALSE(rim.empty());
  std::nth_element(rim.begin(), rim.begin() + std::ptrdiff_t(rim.size() / 2), rim.end());
  EXPECT_EQ(map.bodies()[1].level_m, rim[rim.size() / 2]);

  const WaterMap named = read_water_file(hf, path, std::string("lvl"));
  EXPECT_EQ(named.bodies()[0].level_m, -2.0f);
  EXPECT_EQ(named.bodies()[1].level_m, 1330.0f);
  EXPECT_EQ(named.bodies()[2].level_m, 1201.5f);

  // Placed on the terrain: the samples under each body are its level.
  options::WaterOptions opts;
  opts.source = options::WaterSource::File;
  opts.file = path;
  opts.level_attribute = "lvl";
  const auto placed = place_water(hf, opts);
  ASSERT_TRUE(hf.water);
  EXPECT_EQ(hf.water.get(), placed.get());
  for (int j = 0; j < hf.height; ++j)
    for (int i = 0; i < hf.width; ++i)
      if (const auto b = placed->body_at(i, j)) ASSERT_EQ(hf.at(i, j), placed->bodies()[*b].level_m) << i << "," << j;
  double sum = 0.0;  // the statistics follow
  for (float v : hf.heights) sum += v;
  EXPECT_DOUBLE_EQ(hf.mean_m, sum / double(hf.heights.size()));
}

TEST_F(WaterFile, RasterMaskIsWarpedOntoTheGrid) {
  const terrain::Heightfield hf = make_water_test_terrain();
  // A mask at twice the DEM's resolution over its footprint: two rectangles
  // of 1 (one with a 7 in it: any non-zero is water), nodata 255 in a corner.
  const auto b = *hf.crs_bounds();
  const int w = 2 * hf.width, h = 2 * hf.height;
  std::vector<std::uint8_t> px(std::size_t(w) * h, 0);
  auto north_row = [&](int j_half) { return h - 1 - j_half; };
  for (int jh = 40; jh < 80; ++jh)
    for (int ih = 20; ih < 60; ++ih) px[std::size_t(north_row(jh)) * w + ih] = jh == 50 ? 7 : 1;
  for (int jh = 200; jh < 240; ++jh)
    for (int ih = 300; ih < 340; ++ih) px[std::size_t(north_row(jh)) * w + ih] = 1;
  for (int r = 0; r < 10; ++r)
    for (int c = 0; c < 10; ++c) px[std::size_t(r) * w + c] = 255;
  const std::string path = (dir_ / "mask.tif").string();
  GDALAllRegister();
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), w, h, 1, GDT_Byte, nullptr);
  ASSERT_NE(ds, nullptr);
  double gt[6] = {b[0], (b[2] - b[0]) / w, 0.0, b[3], 0.0, -(b[3] - b[1]) / h};
  GDALSetGeoTransform(ds, gt);
  GDALSetProjection(ds, hf.georef->crs_wkt.c_str());
  GDALSetRasterNoDataValue(GDALGetRasterBand(ds, 1), 255);
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, w, h, px.data(), w, h, GDT_Byte, 0, 0), CE_None);
  GDALClose(ds);

  const WaterMap map = read_water_file(hf, path);
  ASSERT_EQ(map.bodies().size(), 2u);
  // Sample (i, j)'s centre is in half-pixel (2i + 0.5, 2j + 0.5): the
  // nearest half pixel is (2i, 2j) or (2i + 1, 2j + 1), either way inside a
  // rectangle exactly when 2i, 2j are.
  for (int j = 0; j < hf.height; ++j)
    for (int i = 0; i < hf.width; ++i) {
      const bool in_first = 2 * i >= 20 && 2 * i < 60 && 2 * j >= 40 && 2 * j < 80;
      const bool in_second = 2 * i >= 300 && 2 * i < 340 && 2 * j >= 200 && 2 * j < 240;
      ASSERT_EQ(map.is_water(i, j), in_first || in_second) << i << "," << j;
    }
  EXPECT_FALSE(map.is_water(0, hf.height - 1));  // nodata is land
  EXPECT_EQ(map.bodies()[0].samples, 20 * 20);
}

TEST_F(WaterFile, BadFilesAreNamedWithTheReason) {
  const terrain::Heightfield hf = make_water_test_terrain();
  auto has = [](const std::string& error, const std::string& path, const std::string& reason) {
    EXPECT_NE(error.find(path), std::string::npos) << error;
    EXPECT_NE(error.find(reason), std::string::npos) << error;
  };
  const std::string missing = (dir_ / "nowhere.geojson").string();
  has(error_of(hf, missing), missing, "no such file");
  const std::string garbage = write("garbage.geojson", "this is not a GeoJSON file\n");
  has(error_of(hf, garbage), garbage, "GDAL cannot open it");
  const std::string empty = write("empty.geojson", collection({}));
  has(error_of(hf, empty), empty, "is empty");
  const std::string lines = write(
      "lines.geojson", collection({feature(R"({"type":"LineString","coordinates":[[-118.99,37.4],[-118.98,37.41]]})")}));
  has(error_of(hf, lines), lines, "has no polygons");
  const std::string far_away =
      write("far.geojson", collection({feature(polygon("[[[10,10],[11,10],[11,11],[10,11],[10,10]]]"))}));
  has(error_of(hf, far_away), far_away, "do not cover a DEM sample");
  const std::string lake = write(
      "lake.geojson",
      collection({feature(polygon(ring(hf, {{50, 80}, {70, 80}, {70, 100}, {50, 100}})), R"({"name":"a lake"})")}));
  has(error_of(hf, lake, std::string("level")), lake, "has no attribute 'level'");
  has(error_of(hf, lake, std::string("name")), lake, "is not numeric");

  // A shapefile without its .prj: no CRS.
  GDALAllRegister();
  const std::string shp = (dir_ / "nocrs.shp").string();
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("ESRI Shapefile"), shp.c_str(), 0, 0, 0, GDT_Unknown, nullptr);
  ASSERT_NE(ds, nullptr);
  OGRLayerH layer = GDALDatasetCreateLayer(ds, "nocrs", nullptr, wkbPolygon, nullptr);
  OGRFeatureH feat = OGR_F_Create(OGR_L_GetLayerDefn(layer));
  OGRGeometryH g = nullptr;
  char wkt[] = "POLYGON ((-118.95 37.4,-118.9 37.4,-118.9 37.45,-118.95 37.4))";
  char* p = wkt;
  OGR_G_CreateFromWkt(&p, nullptr, &g);
  OGR_F_SetGeometryDirectly(feat, g);
  OGR_L_CreateFeature(layer, feat);
  OGR_F_Destroy(feat);
  GDALClose(ds);
  has(error_of(hf, shp), shp, "no coordinate reference system");

  // A raster without georeferencing, and one elsewhere on Earth.
  const std::string bare = (dir_ / "bare.tif").string();
  ds = GDALCreate(GDALGetDriverByName("GTiff"), bare.c_str(), 8, 8, 1, GDT_Byte, nullptr);
  GDALClose(ds);
  has(error_of(hf, bare), bare, "no coordinate reference system");
  const std::string elsewhere = (dir_ / "elsewhere.tif").string();
  ds = GDALCreate(GDALGetDriverByName("GTiff"), elsewhere.c_str(), 8, 8, 1, GDT_Byte, nullptr);
  double gt[6] = {10.0, 0.01, 0.0, 50.0, 0.0, -0.01};
  GDALSetGeoTransform(ds, gt);
  GDALSetProjection(ds, hf.georef->crs_wkt.c_str());
  GDALClose(ds);
  has(error_of(hf, elsewhere), elsewhere, "does not overlap the DEM");

  // A DEM without georeferencing has nowhere to put them.
  terrain::Heightfield local = hf;
  local.georef.reset();
  has(error_of(local, lake), lake, "has no georeferencing");
}

TEST_F(WaterFile, PlaceWaterFollowsTheSetting) {
  terrain::Heightfield hf = make_water_test_terrain();
  options::WaterOptions opts;
  opts.source = options::WaterSource::Off;
  EXPECT_EQ(place_water(hf, opts), nullptr);
  EXPECT_FALSE(hf.water);
  opts.source = options::WaterSource::Auto;
  const auto found = place_water(hf, opts);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->bodies().size(), 2u);
  EXPECT_EQ(hf.water.get(), found.get());
  // Auto on ground with no water: a map with no bodies, none on the terrain.
  terrain::Heightfield dry = hf;
  for (float& v : dry.heights) v = 500.0f + float(&v - dry.heights.data()) * 0.001f;
  const auto none = place_water(dry, opts);
  ASSERT_TRUE(none);
  EXPECT_TRUE(none->empty());
  EXPECT_FALSE(dry.water);
}

}  // namespace
}  // namespace ig::water

namespace ig::water {
namespace {

// The Must-show case on the real Sierra: terrain.water a GeoJSON polygon
// of Lake Tahoe alone. Water inside it at Tahoe's level, no lake found
// anywhere else (Mono Lake, Walker Lake stay land), the same cells as
// gdal_rasterize burns.
class WaterFileSierra : public WaterFile {};

TEST_F(WaterFileSierra, OneLakePolygonIsTheOnlyWater) {
  const char* dem_dir = std::getenv("IG_DEM_DIR");
  if (!dem_dir || !*dem_dir) GTEST_SKIP() << "IG_DEM_DIR not set: real-DEM tests skipped";
  terrain::Heightfield hf = terrain::load_dem(std::string(dem_dir) + "/sierra_nevada_3arcsec_4097.tif");
  // Inside Tahoe's shore (lon, lat), drawn by hand from the DEM's flat 1 899
  // m; off the sample lattice (a vertex at a round 0.01 degree puts an edge
  // exactly through a column of sample centres, where burning is a tie).
  const std::string path = write(
      "tahoe.geojson",
      R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{"name":"Lake Tahoe"},)"
      R"("geometry":{"type":"Polygon","coordinates":[[[-120.1013,39.2207],[-120.0011,39.2403],[-119.9409,39.2012],)"
      R"([-119.9404,39.0506],[-119.9802,38.9611],[-120.0407,38.9609],[-120.1206,39.0503],[-120.1304,39.1502],)"
      R"([-120.1013,39.2207]]]}}]})");
  options::WaterOptions opts;
  opts.source = options::WaterSource::File;
  opts.file = path;
  const auto map = place_water(hf, opts);
  ASSERT_TRUE(map);
  ASSERT_EQ(map->bodies().size(), 1u);
  EXPECT_EQ(map->bodies()[0].level_m, 1899.0f);  // the flat surface holds most of the polygon
  auto sample = [&](double lat, double lon) {
    const auto xy = terrain::geodetic_to_local(hf, lat, lon);
    return std::pair{int(std::lround(xy->x / hf.spacing_x_m)), int(std::lround(xy->y / hf.spacing_y_m))};
  };
  const auto [ti, tj] = sample(39.09, -120.04);
  EXPECT_TRUE(map->is_water(ti, tj));
  EXPECT_EQ(hf.at(ti, tj), 1899.0f);
  const auto [mi, mj] = sample(37.96, -119.05);  // Mono Lake: found by auto, not in the file
  EXPECT_FALSE(map->is_water(mi, mj));
  const auto [wi, wj] = sample(38.70, -118.72);  // Walker Lake
  EXPECT_FALSE(map->is_water(wi, wj));
  const std::vector<std::uint8_t> burned = gdal_rasterize(hf, path);
  std::int64_t differ = 0;
  for (int j = 0; j < hf.height; ++j)
    for (int i = 0; i < hf.width; ++i) differ += map->is_water(i, j) != (burned[std::size_t(j) * hf.width + i] != 0);
  EXPECT_EQ(differ, 0);
  EXPECT_GT(map->water_samples(), 60000);
}

}  // namespace
}  // namespace ig::water
