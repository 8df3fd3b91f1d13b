#include "terrain/toroidal_window.h"

#include <algorithm>
#include <cstdlib>

namespace ig::terrain {

ToroidalWindow::ToroidalWindow(int dem_w, int dem_h, int size)
    : dem_w_(std::max(dem_w, 1)),
      dem_h_(std::max(dem_h, 1)),
      size_x_(std::clamp(size, 1, dem_w_)),
      size_y_(std::clamp(size, 1, dem_h_)) {}

glm::ivec2 ToroidalWindow::origin_for(glm::ivec2 centre) const {
  return {std::clamp(centre.x - size_x_ / 2, 0, dem_w_ - size_x_), std::clamp(centre.y - size_y_ / 2, 0, dem_h_ - size_y_)};
}

std::vector<SampleRect> ToroidalWindow::move_to(glm::ivec2 to) {
  to = {std::clamp(to.x, 0, dem_w_ - size_x_), std::clamp(to.y, 0, dem_h_ - size_y_)};
  const glm::ivec2 from = origin_;
  const bool first = !placed_;
  placed_ = true;
  origin_ = to;
  if (first || std::abs(to.x - from.x) >= size_x_ || std::abs(to.y - from.y) >= size_y_)
    return {SampleRect{to.x, to.y, size_x_, size_y_}};
  std::vector<SampleRect> out;
  // Columns that came in, over the new window's full height...
  const int dx = to.x - from.x, dy = to.y - from.y;
  if (dx > 0) out.push_back({from.x + size_x_, to.y, dx, size_y_});
  if (dx < 0) out.push_back({to.x, to.y, -dx, size_y_});
  // ...then rows that came in, over the columns not fetched above.
  const int kx0 = to.x - std::min(dx, 0);
  const int kw = size_x_ - std::abs(dx);
  if (dy > 0 && kw > 0) out.push_back({kx0, from.y + size_y_, kw, dy});
  if (dy < 0 && kw > 0) out.push_back({kx0, to.y, kw, -dy});
  return out;
}

glm::ivec2 ToroidalWindow::slot(glm::ivec2 s) const { return {s.x % size_x_, s.y % size_y_}; }

std::vector<SampleRect> ToroidalWindow::split_at_seams(const SampleRect& r) const {
  // A rectangle no larger than the store crosses each seam at most once.
  auto split = [](int a, int n, int size, int out[2][2]) {
    const int first = std::min(n, size - a % size);
    out[0][0] = a;
    out[0][1] = first;
    out[1][0] = a + first;
    out[1][1] = n - first;
  };
  int xs[2][2], ys[2][2];
  split(r.x, r.w, size_x_, xs);
  split(r.y, r.h, size_y_, ys);
  std::vector<SampleRect> out;
  for (auto& y : ys)
    for (auto& x : xs)
      if (x[1] > 0 && y[1] > 0) out.push_back({x[0], y[0], x[1], y[1]});
  return out;
}

}  // namespace ig::terrain
