// The tile cache of paged heights (terrain/height_tile_cache.h): the same
// samples as the whole array, the budget respected, LRU eviction, the
// background loader, misses counted, read errors reported, the
// resident-only reads of a live frame. A synthetic
// reader stands in for GDAL; synchronisation by wait_idle(), never sleeps.
#include "terrain/height_tile_cache.h"

#include <memory>

#include "terrain/height_pyramid.h"
#include "terrain/heightfield_overview.h"
#include "terrain/paged_heights.h"

#include <gtest/gtest.h>

#include <atomic>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

namespace ig::terrain {
namespace {

float value(int i, int j) { return float(i * 1000 + j) * 0.25f; }

HeightTileCache::Reader synthetic(std::atomic<int>* reads = nullptr) {
  return [reads](int, int, int x0, int y0, int w, int h, float* out) {
    if (reads) ++*reads;
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) out[r * w + c] = value(x0 + c, y0 + r);
  };
}

constexpr std::size_t kTileBytes = 16 * 16 * sizeof(float);

TEST(HeightTileCache, SamplesMatchTheWholeArrayIncludingRaggedEdgeTiles) {
  // 100 x 75 in 16^2 tiles: the last column of tiles is 4 wide, the last row 11 high.
  HeightTileCache cache(100, 75, 16, 3 * kTileBytes, synthetic());
  EXPECT_EQ(cache.tiles_x(), 7);
  EXPECT_EQ(cache.tiles_y(), 5);
  for (int j = 0; j < 75; ++j)
    for (int i = 0; i < 100; ++i) ASSERT_EQ(cache.at(i, j), value(i, j)) << i << "," << j;
  std::mt19937 rng(7);
  for (int n = 0; n < 50; ++n) {
    const int x = int(rng() % 100), y = int(rng() % 75);
    const int w = 1 + int(rng() % (100 - x)), h = 1 + int(rng() % (75 - y));
    std::vector<float> dst(std::size_t(w) * h, -1.f);
    cache.read_rect(x, y, w, h, dst.data(), w);
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) ASSERT_EQ(dst[r * w + c], value(x + c, y + r));
  }
}

TEST(HeightTileCache, BudgetIsRespectedAndLeastRecentlyUsedIsEvicted) {
  std::atomic<int> reads{0};
  HeightTileCache cache(64, 64, 16, 3 * kTileBytes, synthetic(&reads));
  cache.at(0, 0);    // tile (0,0)
  cache.at(16, 0);   // (1,0)
  cache.at(32, 0);   // (2,0)
  cache.at(0, 0);    // (0,0) used again: (1,0) is now the least recent
  cache.at(48, 0);   // (3,0): evicts (1,0)
  EXPECT_TRUE(cache.resident(0, 0));
  EXPECT_FALSE(cache.resident(1, 0));
  EXPECT_TRUE(cache.resident(2, 0));
  EXPECT_TRUE(cache.resident(3, 0));
  const auto s = cache.stats();
  EXPECT_EQ(s.misses, 4);  // four distinct tiles paged in on demand
  EXPECT_EQ(reads.load(), 4);
  EXPECT_EQ(s.evictions, 1);
  EXPECT_EQ(s.resident_tiles, 3);
  EXPECT_LE(s.peak_resident_bytes, 3 * kTileBytes);
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) cache.at(i, j);
  EXPECT_LE(cache.stats().peak_resident_bytes, 3 * kTileBytes);
}

TEST(HeightTileCache, BackgroundThreadLoadsRequestedTilesSoReadsDoNotWait) {
  std::atomic<int> reads{0};
  HeightTileCache cache(128, 128, 16, 64 * kTileBytes, synthetic(&reads));
  cache.request(20, 30, 40, 40);  // tiles 1..3 x 1..4: 12 tiles
  cache.wait_idle();
  const auto s = cache.stats();
  EXPECT_EQ(s.prefetched, 12);
  EXPECT_EQ(s.misses, 0);
  for (int j = 30; j < 70; ++j)
    for (int i = 20; i < 60; ++i) ASSERT_EQ(cache.at(i, j), value(i, j));
  EXPECT_EQ(cache.stats().misses, 0);  // all resident already
  EXPECT_EQ(reads.load(), 12);
  cache.request(20, 30, 40, 40);  // resident: nothing queued
  cache.wait_idle();
  EXPECT_EQ(reads.load(), 12);
}

TEST(HeightTileCache, ResidentOnlyReadsQueueInsteadOfWaiting) {
  std::atomic<int> reads{0};
  HeightTileCache cache(128, 128, 16, 64 * kTileBytes, synthetic(&reads));
  EXPECT_FALSE(cache.resident_rect(40, 40, 1, 1));
  EXPECT_FALSE(cache.at_if_resident(40, 40).has_value());  // queued, not read
  EXPECT_FALSE(cache.at_if_resident(30, 49).has_value());
  cache.wait_idle();  // the background thread read what was queued
  EXPECT_EQ(cache.stats().misses, 0);
  EXPECT_EQ(cache.stats().deferred, 2);
  EXPECT_TRUE(cache.resident(2, 2));
  EXPECT_TRUE(cache.resident(1, 3));
  EXPECT_EQ(cache.at_if_resident(40, 40), value(40, 40));  // resident: read
  EXPECT_EQ(cache.stats().deferred, 2);
  EXPECT_EQ(cache.at(70, 70), value(70, 70));  // at() waits (a miss)
  EXPECT_EQ(cache.stats().misses, 1);
  cache.request(0, 0, 128, 128);
  cache.wait_idle();
  EXPECT_TRUE(cache.resident_rect(-5, -5, 200, 200));  // clipped to the grid
}

// The resident-only views a live frame reads through: a sample (or pyramid
// node) over a tile that is not resident counts a miss in the caller's
// TileMisses and reads a fallback (the overview's height; the level-2
// node's bounds), and the tile comes in for the next frame.
TEST(HeightTileCache, ResidentOnlyViewsCountMissesAndFallBack) {
  constexpr int kSize = 129, kStep = 4;
  auto cache = std::make_shared<HeightTileCache>(kSize, kSize, 16, 256 * kTileBytes, synthetic());
  Heightfield whole;
  whole.width = whole.height = kSize;
  whole.heights.resize(std::size_t(kSize) * kSize);
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) whole.ref(i, j) = value(i, j);
  whole.finalize_stats();
  const HeightPyramid full(whole);
  std::vector<HeightPyramid::MinMax> level2;
  for (int j = 0; j < full.level_height(2); ++j)
    for (int i = 0; i < full.level_width(2); ++i) level2.push_back(full.node(2, i, j));
  auto paged = std::make_shared<PagedHeights>();
  paged->cache = cache;
  paged->overview_step = kStep;
  paged->overview = std::make_shared<Heightfield>(decimate_heightfield(whole, kStep));
  paged->pyramid = std::make_shared<const HeightPyramid>(
      HeightPyramid::from_level2(kSize, kSize, cache, level2, full.root()));
  Heightfield hf = whole;
  hf.heights.clear();
  hf.paged = paged;

  TileMisses misses;
  const Heightfield view = hf.resident_only(misses);
  EXPECT_EQ(view.at(41, 42), paged->overview->at(10, 11));  // not resident: the overview's nearest sample
  EXPECT_EQ(misses.count, 1);
  const HeightPyramid pyramid_view = paged->pyramid->resident_only(misses);
  const auto node = pyramid_view.node(0, 81, 82);
  EXPECT_EQ(misses.count, 2);
  EXPECT_EQ(node.lo, paged->pyramid->node(2, 20, 20).lo);  // the level-2 parent's bounds
  EXPECT_EQ(node.hi, paged->pyramid->node(2, 20, 20).hi);
  EXPECT_EQ(cache->stats().misses, 0) << "nothing waited";
  cache->wait_idle();
  EXPECT_EQ(view.at(41, 42), value(41, 42));  // in now: the real sample, no miss
  EXPECT_EQ(pyramid_view.node(0, 81, 82).hi, full.node(0, 81, 82).hi);
  EXPECT_EQ(misses.count, 2);
  EXPECT_THROW(whole.resident_only(misses), std::logic_error);  // whole heights never wait
}

TEST(HeightTileCache, RequestsNeverQueueMoreThanTheBudgetHolds) {
  HeightTileCache cache(256, 256, 16, 5 * kTileBytes, synthetic());
  cache.request(0, 0, 256, 256);  // 256 tiles asked, 5 fit
  cache.wait_idle();
  const auto s = cache.stats();
  EXPECT_EQ(s.prefetched, 5);
  EXPECT_EQ(s.evictions, 0);
  EXPECT_TRUE(cache.resident(7, 7) || cache.resident(8, 8));  // the nearest the centre
}

TEST(HeightTileCache, ConcurrentReadersSeeTheSameSamples) {
  HeightTileCache cache(200, 200, 16, 10 * kTileBytes, synthetic());
  std::atomic<int> wrong{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      std::mt19937 rng(t);
      for (int n = 0; n < 20000; ++n) {
        const int i = int(rng() % 200), j = int(rng() % 200);
        if (cache.at(i, j) != value(i, j)) ++wrong;
      }
    });
  for (int n = 0; n < 50; ++n) cache.request(int(n * 3 % 180), int(n * 7 % 180), 40, 40);
  for (auto& th : threads) th.join();
  cache.wait_idle();
  EXPECT_EQ(wrong.load(), 0);
  EXPECT_LE(cache.stats().peak_resident_bytes, 10 * kTileBytes);
}

TEST(HeightTileCache, ReadErrorsReachTheCallerAndTheBackgroundErrorIsKept) {
  HeightTileCache cache(64, 64, 16, 16 * kTileBytes, [](int tx, int, int, int, int, int, float* out) {
    if (tx == 2) throw std::runtime_error("tile 2 unreadable");
    out[0] = 1.f;
  });
  EXPECT_THROW(cache.at(40, 0), std::runtime_error);
  EXPECT_EQ(cache.at(0, 0), 1.f);
  cache.request(32, 0, 16, 16);
  cache.wait_idle();
  EXPECT_EQ(cache.last_error(), "tile 2 unreadable");
  EXPECT_EQ(cache.stats().read_errors, 1);
  EXPECT_FALSE(cache.resident(2, 0));
}

// try_read_rect never reads: a rectangle with a tile that is not resident is
// refused (nothing copied, nothing counted as a miss), one all resident is
// copied exactly as read_rect would.
TEST(HeightTileCache, TryReadRectCopiesOnlyWhenEveryTileIsResident) {
  std::atomic<int> reads{0};
  HeightTileCache cache(100, 75, 16, 64 * kTileBytes, synthetic(&reads));
  std::vector<float> dst(30 * 20, -1.f);
  EXPECT_EQ(cache.try_read_rect(10, 10, 30, 20, dst.data(), 30), 6);  // tiles 0..2 x 0..1
  EXPECT_EQ(reads.load(), 0);
  EXPECT_EQ(dst[0], -1.f);
  cache.at(10, 10);  // one of them in
  EXPECT_EQ(cache.try_read_rect(10, 10, 30, 20, dst.data(), 30), 5);
  EXPECT_EQ(dst[0], -1.f);
  cache.request(10, 10, 30, 20);
  cache.wait_idle();
  EXPECT_EQ(cache.try_read_rect(10, 10, 30, 20, dst.data(), 30), 0);
  for (int r = 0; r < 20; ++r)
    for (int c = 0; c < 30; ++c) ASSERT_EQ(dst[r * 30 + c], value(10 + c, 10 + r));
  EXPECT_EQ(cache.stats().misses, 1);  // only at()
}

// The same cache over RGB pixels (RgbTileCache, the paged imagery's):
// 3 bytes a pixel in the budget, ragged edge tiles, LRU within the budget.
TEST(RgbTileCache, PixelsMatchAndTheBudgetCountsThreeBytesAPixel) {
  auto colour = [](int i, int j) { return Rgb8{std::uint8_t(i), std::uint8_t(j), std::uint8_t(i ^ j)}; };
  constexpr std::size_t kRgbTile = 16 * 16 * 3;
  RgbTileCache cache(70, 50, 16, 4 * kRgbTile, [&](int, int, int x0, int y0, int w, int h, Rgb8* out) {
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) out[r * w + c] = colour(x0 + c, y0 + r);
  });
  std::vector<Rgb8> all(70 * 50);
  cache.read_rect(0, 0, 70, 50, all.data(), 70);
  for (int j = 0; j < 50; ++j)
    for (int i = 0; i < 70; ++i) ASSERT_EQ(all[j * 70 + i], colour(i, j)) << i << "," << j;
  const auto s = cache.stats();
  EXPECT_EQ(s.misses, 5 * 4);
  EXPECT_LE(s.peak_resident_bytes, 4 * kRgbTile);
  EXPECT_GT(s.evictions, 0);
  EXPECT_EQ(cache.at(69, 49), colour(69, 49));
}

}  // namespace
}  // namespace ig::terrain
