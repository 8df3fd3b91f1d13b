// Water found in the real tiles of $IG_DEM_DIR: Suruga Bay, Lake Tahoe and
// Mono Lake at their levels; Death Valley (below sea level, on the DEM's
// east edge) and the dry bed of Owens Lake stay land; a paged load finds
// exactly what the whole load finds.
#include "water/water_detection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "terrain/dem_loader.h"
#include "terrain/georef.h"

namespace ig::water {
namespace {

namespace fs = std::filesystem;

const char* dem_dir() {
  const char* d = std::getenv("IG_DEM_DIR");
  return (d && *d) ? d : nullptr;
}

// The sample nearest a WGS84 point.
std::pair<int, int> sample_at(const terrain::Heightfield& hf, double lat, double lon) {
  const auto xy = terrain::geodetic_to_local(hf, lat, lon);
  EXPECT_TRUE(xy.has_value());
  return {int(std::lround(xy->x / hf.spacing_x_m)), int(std::lround(xy->y / hf.spacing_y_m))};
}

std::optional<WaterBody> body_at(const terrain::Heightfield& hf, const WaterMap& map, double lat, double lon) {
  const auto [i, j] = sample_at(hf, lat, lon);
  const auto b = map.body_at(i, j);
  if (!b) return std::nullopt;
  return map.bodies()[*b];
}

TEST(WaterDetectionReal, SurugaBayIsTheSeaAndFujisLakesAreLakes) {
  const char* dir = dem_dir();
  if (!dir) GTEST_SKIP() << "IG_DEM_DIR not set: real-DEM tests skipped";
  const terrain::Heightfield hf = terrain::load_dem((fs::path(dir) / "mt_fuji_90m.tif").string());
  const WaterMap map = detect_water(hf);
  for (auto [lat, lon] : {std::pair{35.02, 138.60}, {35.05, 138.65}, {35.00, 138.75}, {35.08, 138.80}}) {
    const auto b = body_at(hf, map, lat, lon);
    ASSERT_TRUE(b) << lat << "," << lon;
    EXPECT_EQ(b->kind, WaterKind::Sea);
    EXPECT_EQ(b->level_m, 0.0f);
    EXPECT_TRUE(b->touches_edge);
    // The count: 56 039 samples at exactly 0 m touch the edge; all
    // but the one-sample-wide fringes (no 2 x 2 block) are the sea.
    EXPECT_GT(b->samples, 55000);
    EXPECT_LE(b->samples, 56039);
  }
  const auto yamanaka = body_at(hf, map, 35.41, 138.87), kawaguchi = body_at(hf, map, 35.515, 138.75);
  ASSERT_TRUE(yamanaka && kawaguchi);
  EXPECT_EQ(yamanaka->level_m, 984.0f);
  EXPECT_EQ(kawaguchi->level_m, 829.0f);
  EXPECT_EQ(yamanaka->kind, WaterKind::Lake);
  // Land: Fuji's summit, Kofu.
  EXPECT_FALSE(body_at(hf, map, 35.3606, 138.7274));
  EXPECT_FALSE(body_at(hf, map, 35.662, 138.568));
}

class WaterDetectionSierra : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const char* dir = dem_dir();
    if (!dir) return;
    path_ = new std::string((fs::path(dir) / "sierra_nevada_3arcsec_4097.tif").string());
    whole_ = new terrain::Heightfield(terrain::load_dem(*path_));
    map_ = new WaterMap(detect_water(*whole_));
  }
  static void TearDownTestSuite() {
    delete map_;
    delete whole_;
    delete path_;
  }
  void SetUp() override {
    if (!dem_dir()) GTEST_SKIP() << "IG_DEM_DIR not set: real-DEM tests skipped";
  }
  static std::string* path_;
  static terrain::Heightfield* whole_;
  static WaterMap* map_;
};
std::string* WaterDetectionSierra::path_ = nullptr;
terrain::Heightfield* WaterDetectionSierra::whole_ = nullptr;
WaterMap* WaterDetectionSierra::map_ = nullptr;

TEST_F(WaterDetectionSierra, TahoeAndMonoLakeAreLakesAtTheirLevels) {
  const auto tahoe = body_at(*whole_, *map_, 39.09, -120.04);
  ASSERT_TRUE(tahoe);
  EXPECT_EQ(tahoe->kind, WaterKind::Lake);
  EXPECT_EQ(tahoe->level_m, 1899.0f);
  EXPECT_GT(tahoe->samples, 74000);  // 74 995 samples at exactly 1 899 m
  EXPECT_LE(tahoe->samples, 74995);
  for (auto [lat, lon] : {std::pair{37.96, -119.05}, {37.99, -118.95}}) {
    const auto mono = body_at(*whole_, *map_, lat, lon);
    ASSERT_TRUE(mono) << lat << "," << lon;
    EXPECT_EQ(mono->level_m, 1943.0f);
    EXPECT_GT(mono->samples, 22000);  // 22 926 at exactly 1 943 m
  }
  EXPECT_FALSE(body_at(*whole_, *map_, 38.01, -119.03));  // Paoha Island, in Mono Lake
}

TEST_F(WaterDetectionSierra, DeathValleyAndOwensLakeStayDry) {
  const terrain::Heightfield& hf = *whole_;
  std::int64_t below_sea = 0;
  for (int j = 0; j < hf.height; ++j)
    for (int i = 0; i < hf.width; ++i)
      if (hf.at(i, j) <= 0.0f) {
        ++below_sea;
        ASSERT_FALSE(map_->is_water(i, j)) << "sample " << i << "," << j << " at " << hf.at(i, j) << " m";
      }
  EXPECT_GT(below_sea, 10000);  // Death Valley's north end is in the DEM
  // Owens Lake's dry bed: the samples below 1 090 m in 36.35-36.52 N,
  // 118.02-117.85 W (a 20-sample pond at 1 093 m on its south-west shore,
  // near Cartago, is flat water in the DEM and counts as a lake).
  const auto [i0, j0] = sample_at(hf, 36.35, -118.02);
  const auto [i1, j1] = sample_at(hf, 36.52, -117.85);
  std::int64_t bed = 0;
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i)
      if (hf.at(i, j) < 1090.0f) {
        ++bed;
        ASSERT_FALSE(map_->is_water(i, j)) << "Owens Lake bed sample " << i << "," << j << " at " << hf.at(i, j) << " m";
      }
  EXPECT_GT(bed, 20000);
  EXPECT_FALSE(body_at(hf, *map_, 36.45, -117.93));
}

TEST_F(WaterDetectionSierra, PagedFindsWhatTheWholeLoadFinds) {
  terrain::DemLoadOptions o;
  o.memory_budget_mb = 32;  // 64 MB of heights: paged
  const terrain::Heightfield paged = terrain::load_dem(*path_, o);
  ASSERT_TRUE(paged.paged);
  const WaterMap p = detect_water(paged);
  EXPECT_TRUE(p == *map_);
  EXPECT_EQ(p.bodies().size(), map_->bodies().size());
}

}  // namespace
}  // namespace ig::water
