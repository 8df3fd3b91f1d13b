#include "terrain/height_pyramid.h"
#include "terrain/huge_pages.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "terrain/paged_heights.h"

namespace ig::terrain {

HeightPyramid::HeightPyramid(const Heightfield& hf) {
  if (hf.paged) {  // built at load; copies share the stored levels
    *this = *hf.paged->pyramid;
    return;
  }
  if (hf.width < 0 || hf.height < 0 ||
      hf.heights.size() != static_cast<std::size_t>(hf.width) * static_cast<std::size_t>(hf.height))
    throw std::invalid_argument("HeightPyramid: heights.size() (" + std::to_string(hf.heights.size()) +
                                ") != width * height (" + std::to_string(hf.width) + " x " +
                                std::to_string(hf.height) + ")");
  if (hf.width < 2 || hf.height < 2) return;  // no cells, empty pyramid
  heights_ = hf.heights.data();
  const auto [lo_it, hi_it] = std::minmax_element(hf.heights.begin(), hf.heights.end());
  root_ = MinMax{*lo_it, *hi_it};
  make_levels(hf.width, hf.height);
  // Level 2 from the level-1 nodes (read from the heights), 2x2 each.
  const Level& c = levels_.size() > 2 ? levels_[1] : Level{};
  encode([&](int i, int j) {
    MinMax m = quad(2 * i, 2 * j);
    for (int cj = 2 * j; cj <= std::min(2 * j + 1, c.ny - 1); ++cj)
      for (int ci = 2 * i; ci <= std::min(2 * i + 1, c.nx - 1); ++ci) {
        const MinMax q = quad(ci, cj);
        m.lo = std::min(m.lo, q.lo);
        m.hi = std::max(m.hi, q.hi);
      }
    return m;
  });
}

HeightPyramid HeightPyramid::from_level2(int width, int height, std::shared_ptr<const HeightTileCache> pages,
                                         const std::vector<MinMax>& level2, MinMax root) {
  HeightPyramid p;
  if (width < 2 || height < 2) return p;
  p.pages_ = std::move(pages);
  p.root_ = root;
  p.make_levels(width, height);
  if (p.levels_.size() > 2 && level2.size() != static_cast<std::size_t>(p.levels_[2].nx) * p.levels_[2].ny)
    throw std::invalid_argument("HeightPyramid::from_level2: " + std::to_string(level2.size()) +
                                " level-2 nodes for a " + std::to_string(width) + " x " + std::to_string(height) +
                                " grid");
  const int nx2 = p.levels_.size() > 2 ? p.levels_[2].nx : 0;
  p.encode([&](int i, int j) { return level2[static_cast<std::size_t>(j) * nx2 + i]; });
  return p;
}

HeightPyramid::MinMax HeightPyramid::paged_node(int i0, int j0, int span) const {
  const int i1 = std::min(i0 + span, width_ - 1), j1 = std::min(j0 + span, height_ - 1);
  if (misses_) {  // resident-only: no wait; the level-2 node holds these samples
    float lo = 0.f, hi = 0.f;
    for (int r = j0; r <= j1; ++r)
      for (int c = i0; c <= i1; ++c) {
        const auto v = pages_->at_if_resident(c, r);
        if (!v) {
          ++misses_->count;
          return levels_.size() > 2 ? node(2, i0 >> 2, j0 >> 2) : root_;
        }
        lo = r == j0 && c == i0 ? *v : std::min(lo, *v);
        hi = r == j0 && c == i0 ? *v : std::max(hi, *v);
      }
    return MinMax{lo, hi};
  }
  float lo = pages_->at(i0, j0), hi = lo;
  for (int r = j0; r <= j1; ++r)
    for (int c = i0; c <= i1; ++c) {
      const float v = pages_->at(c, r);
      lo = v < lo ? v : lo;
      hi = v > hi ? v : hi;
    }
  return MinMax{lo, hi};
}

void HeightPyramid::make_levels(int width, int height) {
  width_ = width;
  height_ = height;
  // Level sizes first so the node array is allocated once; stored levels
  // (>= 2) are padded to whole 2x2 blocks.
  std::size_t total = 0;
  int nx = width - 1, ny = height - 1;
  for (;;) {
    const int bx = (nx + 1) / 2, by = (ny + 1) / 2;
    levels_.push_back(Level{nx, ny, bx, levels_.size() < 2 ? 0 : total});
    if (levels_.size() > 2) total += static_cast<std::size_t>(bx) * static_cast<std::size_t>(by) * 4;
    if (nx == 1 && ny == 1) break;
    nx = (nx + 1) / 2;
    ny = (ny + 1) / 2;
  }
  storage_ = std::make_shared<std::vector<Quantised>>();
  reserve_in_huge_pages(*storage_, total);  // read at scattered places by ray casts
  storage_->assign(total, Quantised{0, 0});
  nodes_ = storage_->data();
}

template <typename Level2>
void HeightPyramid::encode(const Level2& level2_node) {
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
  std::vector<Quantised>& nodes = *storage_;

  {
    const Level& p = levels_[2];
    for (int j = 0; j < p.ny; ++j)
      for (int i = 0; i < p.nx; ++i) {
        const MinMax m = level2_node(i, j);
        nodes[index(p, i, j)] = Quantised{encode_lo(m.lo), encode_hi(m.hi)};
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
        const Quantised a = nodes[index(c, ci0, cj0)], b = nodes[index(c, ci1, cj0)];
        const Quantised d = nodes[index(c, ci0, cj1)], e = nodes[index(c, ci1, cj1)];
        nodes[index(p, i, j)] = Quantised{std::min(std::min(a.lo, b.lo), std::min(d.lo, e.lo)),
                                          std::max(std::max(a.hi, b.hi), std::max(d.hi, e.hi))};
      }
    }
  }
}

}  // namespace ig::terrain
