#include "terrain/height_pyramid.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace ig::terrain {

HeightPyramid::HeightPyramid(const Heightfield& hf) {
  if (hf.width < 0 || hf.height < 0 ||
      hf.heights.size() != static_cast<std::size_t>(hf.width) * static_cast<std::size_t>(hf.height))
    throw std::invalid_argument("HeightPyramid: heights.size() (" + std::to_string(hf.heights.size()) +
                                ") != width * height (" + std::to_string(hf.width) + " x " +
                                std::to_string(hf.height) + ")");
  if (hf.width < 2 || hf.height < 2) return;  // no cells, empty pyramid

  // Level sizes first so the node array is allocated once; each level is
  // padded to whole 2x2 blocks and to a multiple of 8 nodes (64 bytes).
  std::size_t total = 0;
  {
    int nx = hf.width - 1, ny = hf.height - 1;
    for (;;) {
      const int bx = (nx + 1) / 2, by = (ny + 1) / 2;
      levels_.push_back(Level{nx, ny, bx, total});
      total += (static_cast<std::size_t>(bx) * static_cast<std::size_t>(by) * 4 + 7) / 8 * 8;
      if (nx == 1 && ny == 1) break;
      nx = (nx + 1) / 2;
      ny = (ny + 1) / 2;
    }
  }
  // 7 spare nodes so the first level can start on a 64-byte boundary.
  nodes_.assign(total + 7, MinMax{0.f, 0.f});
  const auto addr = reinterpret_cast<std::uintptr_t>(nodes_.data());
  const std::size_t base = ((64 - addr % 64) % 64) / sizeof(MinMax);
  for (Level& l : levels_) l.offset += base;

  // Level 0: per cell min/max of its 4 corners. Reduce each pair of sample
  // rows column-wise first (vectorisable), then adjacent columns.
  {
    const int w = hf.width;
    const Level& l0 = levels_[0];
    std::vector<float> col_lo(static_cast<std::size_t>(w)), col_hi(static_cast<std::size_t>(w));
    for (int j = 0; j < l0.ny; ++j) {
      const float* r0 = hf.heights.data() + static_cast<std::size_t>(j) * w;
      const float* r1 = r0 + w;
      for (int i = 0; i < w; ++i) {
        col_lo[i] = std::min(r0[i], r1[i]);
        col_hi[i] = std::max(r0[i], r1[i]);
      }
      // Cells (i, j) for even i and i + 1 are consecutive in a block row.
      MinMax* out = nodes_.data() + index(l0, 0, j);
      for (int i = 0; i < l0.nx; ++i) {
        MinMax& m = out[(i >> 1) * 4 + (i & 1)];
        m.lo = std::min(col_lo[i], col_lo[i + 1]);
        m.hi = std::max(col_hi[i], col_hi[i + 1]);
      }
    }
  }

  // Higher levels: 2x2 reduction; on an odd-sized child level the last
  // column/row of parents has only one child in that direction.
  for (std::size_t k = 1; k < levels_.size(); ++k) {
    const Level& c = levels_[k - 1];
    const Level& p = levels_[k];
    for (int j = 0; j < p.ny; ++j) {
      const int cj0 = 2 * j;
      const int cj1 = std::min(2 * j + 1, c.ny - 1);
      for (int i = 0; i < p.nx; ++i) {
        const int ci0 = 2 * i;
        const int ci1 = std::min(2 * i + 1, c.nx - 1);
        const MinMax a = nodes_[index(c, ci0, cj0)], b = nodes_[index(c, ci1, cj0)];
        const MinMax d = nodes_[index(c, ci0, cj1)], e = nodes_[index(c, ci1, cj1)];
        MinMax& out = nodes_[index(p, i, j)];
        out.lo = std::min(std::min(a.lo, b.lo), std::min(d.lo, e.lo));
        out.hi = std::max(std::max(a.hi, b.hi), std::max(d.hi, e.hi));
      }
    }
  }
}

}  // namespace ig::terrain
