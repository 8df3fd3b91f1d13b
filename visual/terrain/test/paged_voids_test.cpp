// Voids filled the same when paged (terrain/gdal_tile_reader.h): GeoTIFFs
// with nodata voids across tile edges and corners, made at test time,
// loaded whole and with a 1 MB budget in 64^2 tiles, with the default fill
// (max distance 400) and with short search distances (small ones make the
// paged windows much smaller than the DEM, large ones make deep voids).
// Every sample GDAL fills, and every deep one within kMaxExactDeepLayer
// layers, fills bit for bit as the whole load fills it; deeper ones are
// counted (PagedHeights::inexact_voids) and are the only samples that
// differ; the pyramid built at load bounds the heights the tiles serve
// either way.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <limits>
#include <vector>

#include "terrain/dem_loader.h"
#include "terrain/gdal_tile_reader.h"
#include "terrain/height_pyramid.h"
#include "terrain/heightfield_overview.h"
#include "terrain/paged_heights.h"
#include "terrain/test/paged_checks.h"
#include "terrain/test/temp_dir_fixture.h"
#include "terrain/test/test_geotiff.h"

namespace ig::terrain {
namespace {

namespace fs = std::filesystem;
constexpr float kNodata = -9999.0f;
constexpr int kTile = 64;

struct Rect {
  int x0, y0, x1, y1;  // samples [x0, x1) x [y0, y1), row 0 = south
};

// w x h relief (row 0 = south) with the rectangles made void.
std::vector<float> make_heights(int w, int h, const std::vector<Rect>& voids) {
  std::vector<float> v(std::size_t(w) * h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      v[std::size_t(j) * w + i] = float(1200.0 + 900.0 * std::sin(i * 0.011) * std::cos(j * 0.017) + 0.2 * i +
                                        7.0 * std::sin(i * 1.3 + j * 0.7));
  for (const Rect& r : voids)
    for (int j = r.y0; j < r.y1; ++j)
      for (int i = r.x0; i < r.x1; ++i) v[std::size_t(j) * w + i] = kNodata;
  return v;
}

std::string write_geotiff(const fs::path& path, int w, int h, const std::vector<float>& south_first) {
  test::write_south_first_geotiff(path.string(), w, h, south_first, kNodata);
  return path.string();
}

Heightfield load_paged(const std::string& path, const VoidFillOptions& fill = {}) {
  DemLoadOptions o;
  o.memory_budget_mb = 1;
  o.page_tile = kTile;
  o.void_fill = fill;
  Heightfield hf = load_dem(path, o);
  EXPECT_TRUE(hf.paged);
  return hf;
}

Heightfield load_whole(const std::string& path, const VoidFillOptions& fill = {}) {
  DemLoadOptions o;
  o.void_fill = fill;
  Heightfield hf = load_dem(path, o);
  EXPECT_FALSE(hf.paged);
  return hf;
}

// Every stored pyramid node (levels >= 2) bounds the samples the tiles
// serve under it; levels 0 and 1 are those samples.
void expect_pyramid_bounds_served(const Heightfield& paged) {
  const HeightPyramid p(paged);
  const int w = paged.width, h = paged.height;
  std::vector<float> served(std::size_t(w) * h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) served[std::size_t(j) * w + i] = paged.at(i, j);
  // Exact min/max of level-2 nodes (cells [4i, 4i + 4): samples [4i, 4i + 4]), then up.
  using MinMax = HeightPyramid::MinMax;
  std::vector<MinMax> level(std::size_t(p.level_width(2)) * p.level_height(2));
  for (int nj = 0; nj < p.level_height(2); ++nj)
    for (int ni = 0; ni < p.level_width(2); ++ni) {
      MinMax m{std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()};
      for (int j = 4 * nj; j <= std::min(4 * nj + 4, h - 1); ++j)
        for (int i = 4 * ni; i <= std::min(4 * ni + 4, w - 1); ++i) {
          m.lo = std::min(m.lo, served[std::size_t(j) * w + i]);
          m.hi = std::max(m.hi, served[std::size_t(j) * w + i]);
        }
      level[std::size_t(nj) * p.level_width(2) + ni] = m;
    }
  for (int l = 2; l < p.num_levels(); ++l) {
    const int lw = p.level_width(l), lh = p.level_height(l);
    for (int j = 0; j < lh; ++j)
      for (int i = 0; i < lw; ++i) {
        const MinMax exact = level[std::size_t(j) * lw + i], got = p.node(l, i, j);
        ASSERT_LE(got.lo, exact.lo) << "level " << l << " node " << i << "," << j;
        ASSERT_GE(got.hi, exact.hi) << "level " << l << " node " << i << "," << j;
      }
    if (l + 1 == p.num_levels()) break;
    const int uw = p.level_width(l + 1), uh = p.level_height(l + 1);
    std::vector<MinMax> up(std::size_t(uw) * uh,
                           MinMax{std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()});
    for (int j = 0; j < lh; ++j)
      for (int i = 0; i < lw; ++i) {
        MinMax& u = up[std::size_t(j / 2) * uw + i / 2];
        u.lo = std::min(u.lo, level[std::size_t(j) * lw + i].lo);
        u.hi = std::max(u.hi, level[std::size_t(j) * lw + i].hi);
      }
    level.swap(up);
  }
  const auto [lo, hi] = std::minmax_element(served.begin(), served.end());
  EXPECT_EQ(p.root().lo, *lo);
  EXPECT_EQ(p.root().hi, *hi);
  EXPECT_EQ(paged.min_m, *lo);
  EXPECT_EQ(paged.max_m, *hi);
}

class PagedVoids : public test::TempDirTest {
 protected:
  PagedVoids() : TempDirTest("ig_paged_voids_") {}
};

// Whole and paged loads of `path` with `fill`: the same samples, statistics,
// overview and pyramid.
void expect_paged_equals_whole(const std::string& path, const VoidFillOptions& fill) {
  const Heightfield whole = load_whole(path, fill);
  const Heightfield paged = load_paged(path, fill);
  const int w = whole.width, h = whole.height;
  EXPECT_EQ(paged.nodata_count, whole.nodata_count);
  EXPECT_EQ(paged.deep_void_count, whole.deep_void_count);
  EXPECT_EQ(paged.paged->inexact_voids, 0);
  std::int64_t differ = 0;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) differ += paged.at(i, j) != whole.at(i, j);
  ASSERT_EQ(differ, 0);
  EXPECT_EQ(paged.min_m, whole.min_m);
  EXPECT_EQ(paged.max_m, whole.max_m);
  EXPECT_EQ(paged.mean_m, whole.mean_m);
  ASSERT_NO_FATAL_FAILURE(test::expect_same_overview_and_pyramid(whole, paged, 2));
  expect_pyramid_bounds_served(paged);
}

TEST_F(PagedVoids, FilledBitForBitAcrossTileEdges) {
  const int w = 1100, h = 950;  // ragged last tiles in both directions; wider than the default fill's windows
  const std::vector<Rect> voids = {
      {60, 60, 69, 69},       // across a tile corner (64, 64)
      {120, 10, 136, 300},    // a strip across the x = 128 edge and 4 tile rows
      {0, 250, 40, 262},      // at the DEM's west edge, across y = 256
      {300, 300, 330, 330},   // across the corner (320, 320)
      {500, 180, 650, 330},   // 150^2: beyond small search distances
      {1090, 900, 1100, 950}, // the DEM's north-east corner
      {256, 0, 257, 950},     // a one-sample line the whole height, on a tile edge
      {700, 600, 703, 900},   // a thin strip 300 samples tall
      {800, 700, 900, 702},   // a thin strip 100 samples wide
  };
  const std::string path = write_geotiff(dir_ / "voids.tif", w, h, make_heights(w, h, voids));
  for (const VoidFillOptions fill : {VoidFillOptions{}, VoidFillOptions{24, 2}, VoidFillOptions{24, 0},
                                     VoidFillOptions{6, 5}, VoidFillOptions{90, 1}}) {
    SCOPED_TRACE("max_distance " + std::to_string(fill.max_distance) + ", smoothing " +
                 std::to_string(fill.smoothing_iterations));
    expect_paged_equals_whole(path, fill);
  }
}

TEST_F(PagedVoids, DeepVoidsFillBitForBitWithinTheirLayerLimit) {
  const int w = 700, h = 650;
  // 150^2 with max distance 24: deep samples up to 51 layers in.
  const std::vector<Rect> voids = {{500, 180, 650, 330}, {60, 60, 69, 69}};
  const std::string path = write_geotiff(dir_ / "deep_exact.tif", w, h, make_heights(w, h, voids));
  const VoidFillOptions fill{24, 2};
  const Heightfield whole = load_whole(path, fill);
  EXPECT_GT(whole.deep_void_count, 100 * 100);
  expect_paged_equals_whole(path, fill);
}

TEST_F(PagedVoids, VoidsDeeperThanTheLayerLimitAreCountedAndBounded) {
  const int w = 1100, h = 900;
  // 640^2 with max distance 20: samples more than 20 from every side are
  // deep, their layer is that distance less 20, and those beyond
  // kMaxExactDeepLayer layers (the middle 2 * (320 - 20 - 256) = 88 a side)
  // may differ when paged.
  const VoidFillOptions fill{20, 2};
  const Rect big{230, 130, 870, 770};
  const std::vector<Rect> voids = {big, {60, 60, 69, 69}};
  const std::vector<float> v = make_heights(w, h, voids);
  auto edge_distance = [&](int i, int j) {  // samples to the nearest valid one, straight across a side
    return std::min({i - big.x0 + 1, big.x1 - i, j - big.y0 + 1, big.y1 - j});
  };
  std::int64_t deep = 0, beyond = 0;
  for (int j = big.y0; j < big.y1; ++j)
    for (int i = big.x0; i < big.x1; ++i) {
      deep += edge_distance(i, j) > fill.max_distance;
      beyond += edge_distance(i, j) - fill.max_distance > kMaxExactDeepLayer;
    }
  ASSERT_EQ(beyond, 88 * 88);
  const std::string path = write_geotiff(dir_ / "deep.tif", w, h, v);
  const Heightfield whole = load_whole(path, fill);
  const Heightfield paged = load_paged(path, fill);
  EXPECT_EQ(whole.deep_void_count, deep);
  EXPECT_EQ(paged.nodata_count, whole.nodata_count);
  EXPECT_EQ(paged.deep_void_count, deep);
  EXPECT_EQ(paged.paged->inexact_voids, beyond);
  std::int64_t differ = 0;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      if (paged.at(i, j) == whole.at(i, j)) continue;
      ++differ;
      const bool in_big = i >= big.x0 && i < big.x1 && j >= big.y0 && j < big.y1;
      ASSERT_TRUE(in_big && edge_distance(i, j) - fill.max_distance > kMaxExactDeepLayer)
          << i << "," << j << ": a sample within the layer limit differs";
    }
  EXPECT_GT(differ, 0);
  EXPECT_LE(differ, beyond);
  // Every tile read again after the cache evicted it (270 tiles, 64 fit): the same samples.
  std::vector<float> first(std::size_t(w) * h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) first[std::size_t(j) * w + i] = paged.at(i, j);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) ASSERT_EQ(paged.at(i, j), first[std::size_t(j) * w + i]) << i << "," << j;
  EXPECT_GT(paged.paged->cache->stats().evictions, 0);
  expect_pyramid_bounds_served(paged);
}

}  // namespace
}  // namespace ig::terrain

namespace ig::terrain {
namespace {

// The real DEMs with voids (docs/terrain-data.md "Nodata"): whole and paged
// (1 MB budget, 64^2 tiles) give the same samples.
TEST(PagedVoidsRealDems, SameSamplesAsTheWholeLoad) {
  const char* dir = std::getenv("IG_DEM_DIR");
  if (!dir) GTEST_SKIP() << "IG_DEM_DIR not set";
  for (const char* name : {"mt_everest_90m.tif", "mt_rainier_90m.tif", "mt_fuji_90m.tif"}) {
    const std::string path = std::string(dir) + "/" + name;
    if (!fs::exists(path)) GTEST_SKIP() << path << " missing";
    const Heightfield whole = load_dem(path);
    const Heightfield paged = load_paged(path);
    EXPECT_GT(whole.nodata_count, 0) << name;
    EXPECT_EQ(paged.nodata_count, whole.nodata_count) << name;
    EXPECT_EQ(paged.deep_void_count, whole.deep_void_count) << name;
    EXPECT_EQ(paged.paged->inexact_voids, 0) << name;
    std::int64_t differ = 0;
    for (int j = 0; j < whole.height; ++j)
      for (int i = 0; i < whole.width; ++i) differ += paged.at(i, j) != whole.at(i, j);
    EXPECT_EQ(differ, 0) << name;
    EXPECT_EQ(paged.min_m, whole.min_m) << name;
    EXPECT_EQ(paged.max_m, whole.max_m) << name;
    EXPECT_EQ(paged.mean_m, whole.mean_m) << name;
  }
}

}  // namespace
}  // namespace ig::terrain
