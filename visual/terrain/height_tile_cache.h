#pragma once
// A grid too large to hold whole, paged in square tiles into an LRU cache
// bounded by a byte budget (terrain beyond a memory budget): the
// heights of a DEM (HeightTileCache, float samples) and full-resolution
// imagery (RgbTileCache, RGB8 pixels; terrain/imagery_loader.h). One
// template, TileCache<T>, over the element type. No GL.
//
// Tile (tx, ty) holds samples [tx * T, min((tx + 1) * T, width)) x
// [ty * T, min((ty + 1) * T, height)), row-major, row 0 = south like the
// Heightfield. A Reader fills a tile from the source (terrain/gdal_tile_reader.h
// for a GDAL dataset, any function in tests); the cache calls it on one
// thread at a time.
//
// Two ways a tile comes in:
//  * request(): the caller names a rectangle it will need soon (the height
//    window and the look-at point, every frame); missing tiles are queued,
//    nearest the rectangle's centre first, and a background thread loads
//    them. Queued tiles that no longer fit the budget are dropped (the
//    newest request wins).
//  * at() / read_rect() on a tile that is not resident: the caller blocks
//    until it is loaded (read on the caller's thread, or waiting for the
//    background thread's read of that tile). Each such tile is a "miss",
//    counted in Stats::misses: the frame log's page_waits.
//
// try_read_rect() never blocks: it copies a rectangle only when all of its
// tiles are resident (the imagery window holds its place until they are).
// at_if_resident() never blocks either: a sample of a tile that is not
// resident queues the tile first for the background thread and reads as
// nothing (Stats::deferred; not a miss). It serves the resident-only views
// of Heightfield and HeightPyramid (a live frame's look-at ray cast), which
// count such reads in a TileMisses their caller owns.
//
// Eviction: least recently used first, after every insertion, until the
// resident bytes are within the budget (at least one tile stays, so a
// budget smaller than a tile still works, one tile at a time). Tiles are
// shared_ptr-held, so a reader copying from an evicted tile is safe.
// Thread-safe: at(), read_rect(), request() and stats() may be called from
// any thread.

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace ig::terrain {

// One imagery pixel (RGB8, 3 bytes, as GL_RGB / GL_UNSIGNED_BYTE reads it).
struct Rgb8 {
  std::uint8_t r, g, b;
  bool operator==(const Rgb8& o) const { return r == o.r && g == o.g && b == o.b; }
};
static_assert(sizeof(Rgb8) == 3);

// Reads a resident-only view found not resident (each was queued and read
// a fallback instead); owned by the reader, who checks it after.
struct TileMisses {
  std::int64_t count = 0;
};

template <class T>
class TileCache {
 public:
  using Tile = std::vector<T>;
  // Fills `out` (already sized to the tile's samples) with tile (tx, ty).
  // May throw; a failed background read is retried by the next miss, whose
  // caller sees the exception.
  using Reader = std::function<void(int tx, int ty, int x0, int y0, int w, int h, T* out)>;

  struct Stats {
    std::int64_t misses = 0;       // tiles a caller had to wait for (at / read_rect)
    std::int64_t prefetched = 0;   // tiles the background thread loaded
    std::int64_t read_errors = 0;  // background reads that threw (last_error() says why)
    std::int64_t evictions = 0;
    std::int64_t deferred = 0;     // at_if_resident() reads of tiles not resident (queued, not waited for)
    std::size_t resident_bytes = 0;
    std::size_t peak_resident_bytes = 0;  // after eviction, i.e. what the budget bounds
    int resident_tiles = 0;
  };

  TileCache(int width, int height, int tile_size, std::size_t budget_bytes, Reader reader);
  ~TileCache();
  TileCache(const TileCache&) = delete;
  TileCache& operator=(const TileCache&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  int tile_size() const { return tile_; }
  int tiles_x() const { return tiles_x_; }
  int tiles_y() const { return tiles_y_; }
  std::size_t budget_bytes() const { return budget_; }

  // Sample (i, j), 0 <= i < width, 0 <= j < height.
  T at(int i, int j) const;
  // Sample (i, j) when its tile is resident (marked recently used); else
  // queues the tile first for the background thread and returns nullopt.
  std::optional<T> at_if_resident(int i, int j) const;
  // Samples [x, x + w) x [y, y + h) into dst, rows dst_stride elements apart.
  void read_rect(int x, int y, int w, int h, T* dst, std::size_t dst_stride) const;
  // The same without waiting: copies only if every tile of the rectangle is
  // resident (marking them recently used) and returns 0; otherwise copies
  // nothing and returns how many are not (nothing is queued or counted).
  int try_read_rect(int x, int y, int w, int h, T* dst, std::size_t dst_stride) const;
  // Queues the tiles of [x, x + w) x [y, y + h) (clipped to the DEM) that
  // are not resident for the background thread; marks the resident ones
  // recently used.
  void request(int x, int y, int w, int h) const;
  // Blocks until the background thread has nothing queued or loading.
  void wait_idle() const;
  bool resident(int tx, int ty) const;
  // Every tile of [x, x + w) x [y, y + h) (clipped to the grid) is resident.
  bool resident_rect(int x, int y, int w, int h) const;
  Stats stats() const;
  // The last background read error ("" if none).
  std::string last_error() const;

 private:
  using TilePtr = std::shared_ptr<const Tile>;
  struct Entry {
    TilePtr tile;
    std::list<int>::iterator lru;
  };
  int key(int tx, int ty) const { return ty * tiles_x_ + tx; }
  TilePtr load(int k) const;                     // reads tile k (no lock held)
  TilePtr get(int k) const;                      // resident or paged in now (a miss)
  TilePtr get_if_resident(int k) const;          // null (and queued first) when not resident
  template <class Fetch>
  void copy_rect(int x, int y, int w, int h, T* dst, std::size_t dst_stride, Fetch&& fetch) const;
  void insert_locked(int k, TilePtr t) const;    // + eviction
  void loader_loop();

  int width_, height_, tile_, tiles_x_, tiles_y_;
  std::size_t budget_;
  Reader reader_;

  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;  // a load finished or a request arrived
  mutable std::mutex read_mutex_;            // one Reader call at a time
  mutable std::unordered_map<int, Entry> tiles_;
  mutable std::list<int> lru_;  // front = most recently used
  mutable std::unordered_set<int> loading_;
  mutable std::deque<int> queue_;  // tiles for the background thread, first = next
  mutable Stats stats_;
  mutable std::string last_error_;
  bool stop_ = false;
  std::thread loader_;
};

using HeightTileCache = TileCache<float>;
using RgbTileCache = TileCache<Rgb8>;
extern template class TileCache<float>;
extern template class TileCache<Rgb8>;

}  // namespace ig::terrain
