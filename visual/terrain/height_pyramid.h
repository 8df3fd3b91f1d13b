#pragma once
// Min/max height pyramid (a 2D "maximum mipmap" with minima too) over a
// Heightfield's cells, used to accelerate ray casts against the terrain.
//
// A cell (i, j) is the quad between samples (i, j), (i+1, j), (i, j+1),
// (i+1, j+1); a Heightfield of width x height samples has
// (width-1) x (height-1) cells. Level 0 has one node per cell: the min and
// max of its 4 corner heights (which bound both rendered triangles of the
// quad, since the surface interpolates linearly between corners). Level k+1
// node (i, j) covers level-k nodes (2i..2i+1, 2j..2j+1) — fewer on a ragged
// right/top edge when the level-k size is odd — and bounds their min/max.
// Levels halve (rounding up) in each direction independently until a single
// root node of 1 x 1 remains, so non-square and non-power-of-two grids work.
// A level-k node (i, j) covers cells [i * 2^k, min((i+1) * 2^k, cells_x()))
// in x, and the same in y.
//
// Compact storage (terrain beyond a memory budget): levels 0 and 1
// are not stored, their nodes are read from the heights (exact: 2 x 2 and
// 3 x 3 samples, which the ray cast reads next anyway). Levels >= 2 are
// stored as 16-bit min/max quantised over the whole height range, the
// minimum rounded down and the maximum up (with one step of margin), so
// every node still BOUNDS its cells (lo <= true min, hi >= true max),
// loosened by at most ~3 steps of (max - min) / 65000 (0.07 m on a 4500 m
// range). The root is exact. Memory: 4 bytes per level-2 node (a level-2
// node covers 16 cells) x 4/3, about 0.33 bytes per sample (5.6 MB for
// 4097 x 4097, 140 MB for 20481 x 20481; was 179 MB for 4097 x 4097 at 8
// bytes per cell with a stored float level 0). Bounds that are looser only
// make the ray cast visit a few more nodes; its answers are unchanged.
//
// The pyramid keeps a pointer to the heightfield's heights (level 0): the
// heightfield must outlive the pyramid and its heights must not be
// reallocated. It is a snapshot: rebuild it after editing the heights
// (cast_ray checks the dimensions match but cannot detect edited heights).
//
// Paged heightfields (terrain/paged_heights.h): the loader builds the
// pyramid in its pass over the source (from_level2) and levels 0 and 1 are
// read through the tile cache. Copies share the stored levels, so
// HeightPyramid(paged_hf) costs nothing.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "terrain/height_tile_cache.h"
#include "terrain/heightfield.h"

namespace ig::terrain {

class HeightPyramid {
 public:
  struct MinMax {
    float lo;
    float hi;
  };

  // Empty pyramid (no levels). Only matches a heightfield without cells
  // (cast_ray throws std::invalid_argument for any other heightfield).
  HeightPyramid() = default;
  // Builds all levels. A heightfield narrower or shorter than 2 samples has
  // no cells and gives an empty pyramid. Throws std::invalid_argument when
  // heights.size() != width * height. NaN heights are not supported
  // (loaders fill nodata before this point).
  explicit HeightPyramid(const Heightfield& hf);
  // A pyramid over a width x height grid whose samples are paged: level2 is
  // the exact min/max of every level-2 node (samples [4i, min(4i + 4, width
  // - 1)] x [4j, min(4j + 4, height - 1)]), row-major, and root the exact
  // min/max of all samples. Levels 0 and 1 read through `pages`.
  static HeightPyramid from_level2(int width, int height, std::shared_ptr<const HeightTileCache> pages,
                                   const std::vector<MinMax>& level2, MinMax root);
  // Paged levels 0 and 1 read without waiting (a live frame): a node over a
  // tile that is not resident queues the tile, counts in `misses` and
  // answers its level-2 parent's bounds (conservative). A copy sharing the
  // stored levels; `misses` must outlive it. Whole pyramids never wait.
  HeightPyramid resident_only(TileMisses& misses) const {
    HeightPyramid p = *this;
    if (pages_) p.misses_ = &misses;
    return p;
  }
  // Level-2 nodes a side of a grid of `samples` a side: ceil((samples - 1) / 4).
  static int level2_side(int samples) { return (samples / 2 + 1) / 2; }

  bool empty() const { return levels_.empty(); }
  // Cells (= level-0 nodes) in x and y: width-1 and height-1 of the source.
  int cells_x() const { return levels_.empty() ? 0 : levels_[0].nx; }
  int cells_y() const { return levels_.empty() ? 0 : levels_[0].ny; }
  // Number of levels including level 0 and the 1x1 root (1 for a 2x2 grid).
  int num_levels() const { return static_cast<int>(levels_.size()); }
  int level_width(int level) const { return levels_[level].nx; }
  int level_height(int level) const { return levels_[level].ny; }
  // Bounds of node (i, j) at the given level: exact at levels 0 and 1 (the
  // heights), conservative above (see the top of this file); no bounds
  // checking.
  MinMax node(int level, int i, int j) const {
    if (level == 0) return cell(i, j);
    if (level == 1) return quad(i, j);
    const Quantised q = nodes_[index(levels_[level], i, j)];
    return MinMax{decode(q.lo), decode(q.hi)};
  }
  // Hint for traversals: start fetching the 2x2 block holding node (i, j),
  // what expanding its parent reads (levels 0 and 1: the heights under the
  // block, 3 or 5 rows; each row's first and last sample, which may lie in
  // different cache lines).
  void prefetch(int level, int i, int j) const {
#if defined(__GNUC__) || defined(__clang__)
    if (level <= 1 && !heights_) return;  // paged: read through the cache
    if (level <= 1) {
      const int step = 1 << level;
      const int c0 = (i & ~1) * step, r0 = (j & ~1) * step;
      const int c1 = c0 + 2 * step < width_ ? c0 + 2 * step : width_ - 1;
      const int r1 = r0 + 2 * step < height_ ? r0 + 2 * step : height_ - 1;
      for (int r = r0; r <= r1; ++r) {
        const float* row = heights_ + static_cast<std::size_t>(r) * width_;
        __builtin_prefetch(row + c0);
        __builtin_prefetch(row + c1);
      }
    } else {
      __builtin_prefetch(nodes_ + index(levels_[level], i, j));
    }
#endif
  }
  // Exact min/max of all heights.
  MinMax root() const { return root_; }
  // Bytes held by the stored levels (levels 0 and 1 are read from the heights).
  std::size_t memory_bytes() const { return storage_ ? storage_->size() * sizeof(Quantised) : 0; }

 private:
  struct Quantised {
    std::uint16_t lo, hi;
  };
  // Storage: each stored level (>= 2) is a row-major grid of 2x2 blocks of
  // nodes, a block being 4 consecutive Quantised ((0,0), (1,0), (0,1),
  // (1,1)), so the 4 children of a node are read together. Odd-sized
  // levels are padded to whole blocks (padding nodes are never read).
  struct Level {
    int nx = 0, ny = 0;
    int blocks_x = 0;
    std::size_t offset = 0;  // into nodes_ (unused for level 0)
  };
  static std::size_t index(const Level& l, int i, int j) {
    return l.offset + (static_cast<std::size_t>(j >> 1) * l.blocks_x + (i >> 1)) * 4 + ((j & 1) << 1) + (i & 1);
  }
  MinMax cell(int i, int j) const {
    if (!heights_) return paged_node(i, j, 1);
    const float* r0 = heights_ + static_cast<std::size_t>(j) * width_ + i;
    const float* r1 = r0 + width_;
    const float a = r0[0], b = r0[1], c = r1[0], d = r1[1];
    const float lo0 = a < b ? a : b, lo1 = c < d ? c : d, hi0 = a < b ? b : a, hi1 = c < d ? d : c;
    return MinMax{lo0 < lo1 ? lo0 : lo1, hi0 < hi1 ? hi1 : hi0};
  }
  // Level-1 node: samples 2i..2i+2 x 2j..2j+2, fewer at the east / north edge.
  MinMax quad(int i, int j) const {
    if (!heights_) return paged_node(2 * i, 2 * j, 2);
    const int i0 = 2 * i, j0 = 2 * j;
    const int i1 = i0 + 2 < width_ ? i0 + 2 : width_ - 1, j1 = j0 + 2 < height_ ? j0 + 2 : height_ - 1;
    float lo = heights_[static_cast<std::size_t>(j0) * width_ + i0], hi = lo;
    for (int r = j0; r <= j1; ++r) {
      const float* row = heights_ + static_cast<std::size_t>(r) * width_;
      for (int c = i0; c <= i1; ++c) {
        lo = row[c] < lo ? row[c] : lo;
        hi = row[c] > hi ? row[c] : hi;
      }
    }
    return MinMax{lo, hi};
  }
  // Min/max of samples [i0, min(i0 + span, width - 1)] x [j0, ...] read through the cache.
  MinMax paged_node(int i0, int j0, int span) const;
  void make_levels(int width, int height);  // levels_ and the storage, zeroed
  template <typename Level2>
  void encode(const Level2& level2_node);  // levels >= 2 from exact level-2 bounds; root_ set
  float decode(std::uint16_t q) const { return base_ + static_cast<float>(q) * step_; }

  std::vector<Level> levels_;
  std::shared_ptr<std::vector<Quantised>> storage_;  // shared by copies
  const Quantised* nodes_ = nullptr;                  // storage_->data()
  const float* heights_ = nullptr;  // the heightfield's (level 0); null when paged
  std::shared_ptr<const HeightTileCache> pages_;      // paged level 0
  TileMisses* misses_ = nullptr;                      // set in a resident-only view
  int width_ = 0, height_ = 0;       // samples per row / rows of heights_
  MinMax root_{0.f, 0.f};
  float base_ = 0.f, step_ = 1.f;  // height = base_ + q * step_
};

}  // namespace ig::terrain
