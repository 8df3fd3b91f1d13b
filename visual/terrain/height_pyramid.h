#pragma once
// Min/max height pyramid (a 2D "maximum mipmap" with minima too) over a
// Heightfield's cells, used to accelerate ray casts against the terrain.
//
// A cell (i, j) is the quad between samples (i, j), (i+1, j), (i, j+1),
// (i+1, j+1); a Heightfield of width x height samples has
// (width-1) x (height-1) cells. Level 0 holds one node per cell: the min and
// max of its 4 corner heights (which bound both rendered triangles of the
// quad, since the surface interpolates linearly between corners). Level k+1
// node (i, j) covers level-k nodes (2i..2i+1, 2j..2j+1) — fewer on a ragged
// right/top edge when the level-k size is odd — and stores their min/max.
// Levels halve (rounding up) in each direction independently until a single
// root node of 1 x 1 remains, so non-square and non-power-of-two grids work.
// A level-k node (i, j) covers cells [i * 2^k, min((i+1) * 2^k, cells_x()))
// in x, and the same in y.
//
// Memory: 8 bytes per level-0 node, about 8 * 4/3 bytes per cell overall
// (~180 MB for a 4097 x 4097 DEM, i.e. ~2.7x the float heights). Build time
// ~0.15-0.2 s for 4097 x 4097 on one core (see docs/ray-cast.md).
//
// The pyramid is a snapshot: rebuild it after editing the heights (cast_ray
// checks the dimensions match but cannot detect edited heights).

#include <cstddef>
#include <cstdint>
#include <vector>

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

  bool empty() const { return levels_.empty(); }
  // Cells (= level-0 nodes) in x and y: width-1 and height-1 of the source.
  int cells_x() const { return levels_.empty() ? 0 : levels_[0].nx; }
  int cells_y() const { return levels_.empty() ? 0 : levels_[0].ny; }
  // Number of levels including level 0 and the 1x1 root (1 for a 2x2 grid).
  int num_levels() const { return static_cast<int>(levels_.size()); }
  int level_width(int level) const { return levels_[level].nx; }
  int level_height(int level) const { return levels_[level].ny; }
  // Min/max height of node (i, j) at the given level; no bounds checking.
  MinMax node(int level, int i, int j) const { return nodes_[index(levels_[level], i, j)]; }
  // Hint for traversals: start fetching the 2x2 block holding node (i, j).
  void prefetch(int level, int i, int j) const {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(nodes_.data() + index(levels_[level], i, j));
#endif
  }
  MinMax root() const { return nodes_[index(levels_.back(), 0, 0)]; }
  // Bytes held by the node array.
  std::size_t memory_bytes() const { return nodes_.size() * sizeof(MinMax); }

 private:
  // Storage: each level is a row-major grid of 2x2 blocks of nodes, a block
  // being 4 consecutive MinMax (32 bytes: (0,0), (1,0), (0,1), (1,1)), so the
  // 4 children of a node share one cache line. Odd-sized levels are padded
  // to whole blocks (padding nodes are never read). Levels start at 64-byte
  // boundaries of the buffer, counted from base_ (aligned when built).
  struct Level {
    int nx = 0, ny = 0;
    int blocks_x = 0;
    std::size_t offset = 0;  // into nodes_, including base_
  };
  static std::size_t index(const Level& l, int i, int j) {
    return l.offset + (static_cast<std::size_t>(j >> 1) * l.blocks_x + (i >> 1)) * 4 + ((j & 1) << 1) + (i & 1);
  }
  std::vector<Level> levels_;
  std::vector<MinMax> nodes_;
};

}  // namespace ig::terrain
