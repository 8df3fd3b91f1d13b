#include "terrain/height_pyramid.h"

#include "terrain/huge_pages.h"

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
  height_ = hf.height;

  // Level sizes first so the node array is allocated once; stored levels
  // (>= 2) are padded to whole 2x2 blocks.
  std::size_t total = 0;
  {
    int nx = hf.width - 1, ny = hf.height - 1;
    for (;;) {
      const int bx = (nx + 1) / 2, by = (ny + 1) / 2;
      levels_.push_back(Level{nx, ny, bx, levels_.size() < 2 ? 0 : total});
      if (levels_.size() > 2) total += static_cast<std::size_t>(bx) * static_cast<std::size_t>(by) * 4;
      if (nx == 1 && ny == 1) break;
      nx = (nx + 1) / 2;
      ny = (ny + 1) / 2;
    }
  }

  const auto [lo_it, hi_it] = std::minmax_element(hf.heights.begin(), hf.heights.end());
  root_ = MinMax{*lo_it, *hi_it};
  if (levels_.size() <= 2) return;  // levels 0 and 1 are all there is

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

  reserve_in_huge_pages(nodes_, total);  // read at scattered places by ray casts
  nodes_.assign(total, Quantised{0, 0});

  // Level 2 from the level-1 nodes (read from the heights), 2x2 each.
  {
    const Level& c = levels_[1];
    const Level& p = levels_[2];
    for (int j = 0; j < p.ny; ++j)
      for (int i = 0; i < p.nx; ++i) {
        MinMax m = quad(2 * i, 2 * j);
        for (int cj = 2 * j; cj <= std::min(2 * j + 1, c.ny - 1); ++cj)
          for (int ci = 2 * i; ci <= std::min(2 * i + 1, c.nx - 1); ++ci) {
            const MinMax q = quad(ci, cj);
            m.lo = std::min(m.lo, q.lo);
            m.hi = std::max(m.hi, q.hi);
          }
        nodes_[index(p, i, j)] = Quantised{encode_lo(m.lo), encode_hi(m.hi)};
      }
  }

  // Higher levels: 2x2 reduction of the codes (monotone, so still bounds);
  // on an odd-sized child level the last column/row of parents has only one
  // child in that direction.
  for (std::size_t k = 3; k < levels_.size(); ++k) {
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
