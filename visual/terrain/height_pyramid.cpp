#include "terrain/height_pyramid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
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
  heights_ = hf.heights.data();
  width_ = hf.width;

  // Level sizes first so the node array is allocated once; stored levels
  // (>= 1) are padded to whole 2x2 blocks.
  std::size_t total = 0;
  {
    int nx = hf.width - 1, ny = hf.height - 1;
    for (;;) {
      const int bx = (nx + 1) / 2, by = (ny + 1) / 2;
      levels_.push_back(Level{nx, ny, bx, levels_.empty() ? 0 : total});
      if (levels_.size() > 1) total += static_cast<std::size_t>(bx) * static_cast<std::size_t>(by) * 4;
      if (nx == 1 && ny == 1) break;
      nx = (nx + 1) / 2;
      ny = (ny + 1) / 2;
    }
  }

  const auto [lo_it, hi_it] = std::minmax_element(hf.heights.begin(), hf.heights.end());
  root_ = MinMax{*lo_it, *hi_it};
  if (levels_.size() == 1) return;  // a single cell: level 0 is all there is

  // Quantisation: steps of range / 65000 (headroom above the top code), and
  // at least 4 float ulps of the largest height, so that a one-step margin
  // covers any last-bit difference in how decode() is compiled (e.g. fused
  // multiply-add in one translation unit and not in another).
  const double range = double(root_.hi) - double(root_.lo);
  const double mag = std::max(std::abs(double(root_.lo)), std::abs(double(root_.hi)));
  base_ = root_.lo;
  step_ = static_cast<float>(std::max({range / 65000.0, 4.0 * mag * std::ldexp(1.0, -23), 1e-30}));
  const auto encode_lo = [&](float lo) {
    double q = std::floor((double(lo) - double(base_)) / double(step_)) - 1.0;
    auto c = static_cast<std::uint16_t>(std::clamp(q, 0.0, 65535.0));
    while (c > 0 && decode(c) > lo) --c;  // conservative whatever the rounding
    return c;
  };
  const auto encode_hi = [&](float hi) {
    double q = std::ceil((double(hi) - double(base_)) / double(step_)) + 1.0;
    auto c = static_cast<std::uint16_t>(std::clamp(q, 0.0, 65535.0));
    while (c < 65535 && decode(c) < hi) ++c;
    return c;
  };

  nodes_.assign(total, Quantised{0, 0});

  // Level 1 straight from the heights: a level-1 node covers cells 2i..2i+1,
  // i.e. samples 2i..2i+2 (fewer at a ragged edge). Reduce the node row's
  // sample rows column-wise first (vectorisable), then the columns.
  {
    const int w = hf.width, h = hf.height;
    const Level& l1 = levels_[1];
    std::vector<float> col_lo(static_cast<std::size_t>(w)), col_hi(static_cast<std::size_t>(w));
    for (int j = 0; j < l1.ny; ++j) {
      const int s0 = 2 * j, s1 = std::min(2 * j + 2, h - 1);
      const float* r0 = hf.heights.data() + static_cast<std::size_t>(s0) * w;
      std::copy(r0, r0 + w, col_lo.begin());
      std::copy(r0, r0 + w, col_hi.begin());
      for (int s = s0 + 1; s <= s1; ++s) {
        const float* r = hf.heights.data() + static_cast<std::size_t>(s) * w;
        for (int i = 0; i < w; ++i) {
          col_lo[i] = std::min(col_lo[i], r[i]);
          col_hi[i] = std::max(col_hi[i], r[i]);
        }
      }
      for (int i = 0; i < l1.nx; ++i) {
        const int c0 = 2 * i, c1 = std::min(2 * i + 2, w - 1);
        float lo = col_lo[c0], hi = col_hi[c0];
        for (int c = c0 + 1; c <= c1; ++c) {
          lo = std::min(lo, col_lo[c]);
          hi = std::max(hi, col_hi[c]);
        }
        nodes_[index(l1, i, j)] = Quantised{encode_lo(lo), encode_hi(hi)};
      }
    }
  }

  // Higher levels: 2x2 reduction of the codes (monotone, so still bounds);
  // on an odd-sized child level the last column/row of parents has only one
  // child in that direction.
  for (std::size_t k = 2; k < levels_.size(); ++k) {
    const Level& c = levels_[k - 1];
    const Level& p = levels_[k];
    for (int j = 0; j < p.ny; ++j) {
      const int cj0 = 2 * j;
      const int cj1 = std::min(2 * j + 1, c.ny - 1);
      for (int i = 0; i < p.nx; ++i) {
        const int ci0 = 2 * i;
        const int ci1 = std::min(2 * i + 1, c.nx - 1);
        const Quantised a = nodes_[index(c, ci0, cj0)], b = nodes_[index(c, ci1, cj0)];
        const Quantised d = nodes_[index(c, ci0, cj1)], e = nodes_[index(c, ci1, cj1)];
        nodes_[index(p, i, j)] = Quantised{std::min(std::min(a.lo, b.lo), std::min(d.lo, e.lo)),
                                           std::max(std::max(a.hi, b.hi), std::max(d.hi, e.hi))};
      }
    }
  }
}

}  // namespace ig::terrain
