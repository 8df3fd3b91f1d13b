#include "terrain/void_fill_halo.h"

#include <algorithm>
#include <cmath>

namespace ig::terrain {

int full_fill_halo(const VoidFillOptions& opts) { return opts.max_distance + 1 + opts.smoothing_iterations; }

int exact_fill_halo(const std::vector<std::uint8_t>& valid, const FillWindow& win, const VoidFillOptions& opts) {
  const int md = opts.max_distance, smoothing = opts.smoothing_iterations;
  const int full = full_fill_halo(opts);
  const int w = win.width, ht = win.height;
  // The voids whose interpolated values the rectangle's smoothed ones read.
  const int x0 = std::max(0, win.rect_x0 - smoothing), x1 = std::min(w, win.rect_x0 + win.rect_width + smoothing);
  const int y0 = std::max(0, win.rect_y0 - smoothing), y1 = std::min(ht, win.rect_y0 + win.rect_height + smoothing);
  if (x0 >= x1 || y0 >= y1) return std::min(full, smoothing + 1);
  auto is_valid = [&](int i, int j) { return valid[std::size_t(j) * w + i] != 0; };

  // For columns x0 .. x1 (x1: the east neighbour of the last), rows y0 .. y1 - 1:
  // rows to the nearest valid sample north, this row included (GDAL's
  // top-down candidate), and south, this row excluded (its bottom-up one);
  // -1 when the window has none.
  const int cols = std::min(w, x1 + 1) - x0, rows = y1 - y0;
  std::vector<int> north(std::size_t(cols) * rows), south(std::size_t(cols) * rows);
  for (int c = 0; c < cols; ++c) {
    const int i = x0 + c;
    int nearest = -1;  // row of the nearest valid sample at or north of j
    for (int j = ht - 1; j >= y0; --j) {
      if (is_valid(i, j)) nearest = j;
      if (j < y1) north[std::size_t(c) * rows + (j - y0)] = nearest < 0 ? -1 : nearest - j;
    }
    nearest = -1;  // row of the nearest valid sample south of j
    for (int j = 0; j < y1; ++j) {
      if (j >= y0) south[std::size_t(c) * rows + (j - y0)] = nearest < 0 ? -1 : j - nearest;
      if (is_valid(i, j)) nearest = j;
    }
  }

  int need = smoothing + 1;  // the window's first and last rows are never smoothed
  for (int j = y0; j < y1; ++j)
    for (int i = x0; i < x1; ++i) {
      if (is_valid(i, j)) continue;
      // GDAL's east column, the sample's own at the grid's east edge.
      const int east = i + 1 < w ? i + 1 : (win.east_is_grid_edge ? i : -1);
      if (east < 0) return full;
      const std::size_t at = std::size_t(i - x0) * rows + (j - y0), at_east = std::size_t(east - x0) * rows + (j - y0);
      const int d_north = north[at], d_south = south[at], e_north = north[at_east], e_south = south[at_east];
      if (d_north < 0 || d_south < 0 || e_north < 0 || e_south < 0) return full;
      const double dx = east - i;
      const double b = std::max({double(d_north), double(d_south), std::hypot(dx, double(e_north)),
                                 std::hypot(dx, double(e_south))});
      if (b > md) return full;
      const int reach = std::min(md + 1, std::max(4, int(std::ceil(b))) + 1);
      // How far the sample lies outside the rectangle (Chebyshev).
      const int outside = std::max({win.rect_x0 - i, i - (win.rect_x0 + win.rect_width - 1),
                                    win.rect_y0 - j, j - (win.rect_y0 + win.rect_height - 1), 0});
      need = std::max(need, outside + reach);
    }
  return std::min(need, full);
}

}  // namespace ig::terrain
