// Paged heights (terrain/paged_dem_loader.h): a 1025^2 GeoTIFF
// made at test time, loaded whole and with a 1 MB budget (paged in 64^2
// tiles), gives the same samples, statistics, overview, pyramid, ray casts
// and host queries.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <vector>

#include "terrain/dem_loader.h"
#include "terrain/height_pyramid.h"
#include "terrain/heightfield_overview.h"
#include "terrain/paged_heights.h"
#include "terrain/ray_cast.h"
#include "terrain/terrain_query.h"
#include "terrain/test/paged_checks.h"
#include "terrain/test/test_geotiff.h"

namespace ig::terrain {
namespace {

namespace fs = std::filesystem;
constexpr int kSide = 1025;

// Rough relief with three isolated voids (voids across tile edges and deep
// ones: paged_voids_test.cpp).
std::string write_dem(const fs::path& dir, int w = kSide, int h = kSide) {
  const std::string path = (dir / ("paged_" + std::to_string(w) + "x" + std::to_string(h) + ".tif")).string();
  std::vector<float> v(std::size_t(w) * h);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> noise(-15.f, 15.f);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      v[std::size_t(r) * w + c] =
          float(1200.0 + 900.0 * std::sin(c * 0.011) * std::cos(r * 0.017) + 0.2 * c) + noise(rng);
  for (auto [c, r] : {std::pair{100, 100}, {300, 517}, {700, 900}})
    if (c < w && r < h) v[std::size_t(r) * w + c] = -9999.f;
  test::write_test_geotiff(path, w, h, v, -9999.0);
  return path;
}

class PagedDem : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("ig_paged_dem_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    const std::string path = write_dem(dir_);
    whole_ = new Heightfield(load_dem(path));
    DemLoadOptions o;
    o.memory_budget_mb = 1;  // 4.2 MB of heights: paged
    o.page_tile = 64;
    paged_ = new Heightfield(load_dem(path, o));
  }
  static void TearDownTestSuite() {
    delete whole_;
    delete paged_;
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  static fs::path dir_;
  static Heightfield* whole_;
  static Heightfield* paged_;
};
fs::path PagedDem::dir_;
Heightfield* PagedDem::whole_ = nullptr;
Heightfield* PagedDem::paged_ = nullptr;

TEST_F(PagedDem, SameSamplesAndStatisticsWithinTheBudget) {
  const Heightfield& w = *whole_;
  const Heightfield& p = *paged_;
  ASSERT_FALSE(w.paged);
  ASSERT_TRUE(p.paged);
  EXPECT_TRUE(p.heights.empty());
  EXPECT_EQ(p.width, w.width);
  EXPECT_EQ(p.height, w.height);
  EXPECT_EQ(p.spacing_x_m, w.spacing_x_m);
  EXPECT_EQ(p.spacing_y_m, w.spacing_y_m);
  EXPECT_EQ(p.min_m, w.min_m);
  EXPECT_EQ(p.max_m, w.max_m);
  EXPECT_EQ(p.mean_m, w.mean_m);
  EXPECT_EQ(p.nodata_count, 3);
  EXPECT_EQ(p.nodata_count, w.nodata_count);
  ASSERT_TRUE(p.georef && w.georef);
  EXPECT_EQ(p.georef->grid_to_crs, w.georef->grid_to_crs);
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i) ASSERT_EQ(p.at(i, j), w.at(i, j)) << i << "," << j;
  const auto s = p.paged->cache->stats();
  EXPECT_LE(s.peak_resident_bytes, std::size_t(1) << 20);
  EXPECT_GT(s.evictions, 0);
  EXPECT_EQ(dem_info_json(p), dem_info_json(w));
}

TEST_F(PagedDem, OverviewAndPyramidMatchTheWholeArrays) {
  const Heightfield& w = *whole_;
  const Heightfield& p = *paged_;
  const int step = p.paged->overview_step;
  EXPECT_EQ(step, overview_step_for(kSide, kSide, 4097));
  const Heightfield o = decimate_heightfield(w, step);
  EXPECT_EQ(p.paged->overview->heights, o.heights);
  EXPECT_EQ(p.paged->overview->min_m, o.min_m);
  const HeightPyramid pw(w);
  const HeightPyramid pp(p);  // shares the one built at load
  ASSERT_EQ(pp.num_levels(), pw.num_levels());
  EXPECT_EQ(pp.memory_bytes(), pw.memory_bytes());
  EXPECT_EQ(pp.root().lo, pw.root().lo);
  EXPECT_EQ(pp.root().hi, pw.root().hi);
  for (int l = 0; l < pw.num_levels(); ++l) {
    const int stride = l == 0 ? 7 : 1;  // level 0 sampled (it is the heights themselves)
    for (int j = 0; j < pw.level_height(l); j += stride)
      for (int i = 0; i < pw.level_width(l); i += stride) {
        ASSERT_EQ(pp.node(l, i, j).lo, pw.node(l, i, j).lo) << l << ":" << i << "," << j;
        ASSERT_EQ(pp.node(l, i, j).hi, pw.node(l, i, j).hi) << l << ":" << i << "," << j;
      }
  }
}

TEST_F(PagedDem, RayCastsAndHostQueriesGiveTheSameAnswers) {
  const Heightfield& w = *whole_;
  const Heightfield& p = *paged_;
  const HeightPyramid pw(w), pp(p);
  const TerrainQuery qw(w, pw, 0.0), qp(p, pp, 0.0);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int hits = 0;
  for (int n = 0; n < 300; ++n) {
    const glm::dvec3 o(u(rng) * w.extent_x_m(), u(rng) * w.extent_y_m(), 2500.0 + 500.0 * u(rng));
    const glm::dvec3 d(u(rng) - 0.5, u(rng) - 0.5, -0.05 - 0.3 * u(rng));
    const auto a = cast_ray(w, pw, o, d), b = cast_ray(p, pp, o, d);
    ASSERT_EQ(a.has_value(), b.has_value());
    if (a) {
      ++hits;
      EXPECT_EQ(a->t, b->t);
      EXPECT_EQ(a->cell_i, b->cell_i);
      EXPECT_EQ(a->cell_j, b->cell_j);
    }
    const auto sa = qw.surface_at(o.x, o.y), sb = qp.surface_at(o.x, o.y);
    ASSERT_TRUE(sa && sb);
    EXPECT_EQ(sa->height_m, sb->height_m);
    EXPECT_EQ(w.sample_surface(o.x, o.y), p.sample_surface(o.x, o.y));
  }
  EXPECT_GT(hits, 100);
}

TEST_F(PagedDem, RaggedSizesGiveTheSamePyramidAndOverview) {
  // Odd level sizes and partial edge tiles in both directions (1001 x 701
  // samples: 1000 and 700 cells, levels 500 x 350, 250 x 175, 125 x 88, ...),
  // and 1000 x 701 (odd cells in x).
  for (const auto& [w, h] : {std::pair{1001, 701}, {1000, 701}}) {
    const std::string path = write_dem(dir_, w, h);
    const Heightfield whole = load_dem(path);
    DemLoadOptions o;
    o.memory_budget_mb = 1;
    o.page_tile = 48;
    const Heightfield paged = load_dem(path, o);
    ASSERT_TRUE(paged.paged);
    EXPECT_EQ(paged.mean_m, whole.mean_m);
    for (int j = 0; j < h; j += 3)
      for (int i = 0; i < w; ++i) ASSERT_EQ(paged.at(i, j), whole.at(i, j)) << i << "," << j;
    ASSERT_NO_FATAL_FAILURE(test::expect_same_overview_and_pyramid(
        whole, paged, 1, std::to_string(w) + "x" + std::to_string(h) + " "));
  }
}

TEST_F(PagedDem, DemsWithinTheBudgetAreNotPaged) {
  EXPECT_FALSE(whole_->paged);
  EXPECT_EQ(whole_->heights.size(), std::size_t(kSide) * kSide);
}

}  // namespace
}  // namespace ig::terrain
