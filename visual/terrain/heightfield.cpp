#include "terrain/heightfield.h"
#include "terrain/height_tile_cache.h"
#include "terrain/paged_heights.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ig::terrain {

float Heightfield::paged_at(int i, int j) const {
  if (!resident_misses) return paged->cache->at(i, j);
  if (const auto v = paged->cache->at_if_resident(i, j)) return *v;
  ++resident_misses->count;
  const double step = paged->overview_step;
  return paged->overview->at_clamped(int(std::lround(i / step)), int(std::lround(j / step)));
}

Heightfield Heightfield::resident_only(TileMisses& misses) const {
  if (!paged) throw std::logic_error("Heightfield::resident_only: heights held whole");
  Heightfield view;
  view.width = width;
  view.height = height;
  view.spacing_x_m = spacing_x_m;
  view.spacing_y_m = spacing_y_m;
  view.paged = paged;
  view.min_m = min_m;
  view.max_m = max_m;
  view.mean_m = mean_m;
  view.resident_misses = &misses;
  return view;
}

float Heightfield::at_clamped(int i, int j) const {
  i = std::clamp(i, 0, width - 1);
  j = std::clamp(j, 0, height - 1);
  return at(i, j);
}

namespace {
// The quad holding local (x, y) (clamped onto the grid): its corner heights
// and the position inside it.
struct Cell {
  double fx, fy, h00, h10, h01, h11;
};
Cell cell_at(const Heightfield& hf, double x_m, double y_m) {
  const double gx = std::clamp(x_m / hf.spacing_x_m, 0.0, double(hf.width - 1));
  const double gy = std::clamp(y_m / hf.spacing_y_m, 0.0, double(hf.height - 1));
  const int i = std::min(int(gx), std::max(hf.width - 2, 0));
  const int j = std::min(int(gy), std::max(hf.height - 2, 0));
  return {gx - i, gy - j, hf.at_clamped(i, j), hf.at_clamped(i + 1, j), hf.at_clamped(i, j + 1),
          hf.at_clamped(i + 1, j + 1)};
}
}  // namespace

double Heightfield::sample_bilinear(double x_m, double y_m) const {
  const Cell c = cell_at(*this, x_m, y_m);
  return (c.h00 * (1 - c.fx) + c.h10 * c.fx) * (1 - c.fy) + (c.h01 * (1 - c.fx) + c.h11 * c.fx) * c.fy;
}

double Heightfield::sample_surface(double x_m, double y_m) const {
  const Cell c = cell_at(*this, x_m, y_m);
  if (c.fx >= c.fy)  // triangle (i,j) (i+1,j) (i+1,j+1)
    return c.h00 + (c.h10 - c.h00) * c.fx + (c.h11 - c.h10) * c.fy;
  // triangle (i,j) (i+1,j+1) (i,j+1)
  return c.h00 + (c.h01 - c.h00) * c.fy + (c.h11 - c.h01) * c.fx;
}

std::optional<std::array<double, 4>> Heightfield::crs_bounds() const {
  if (!georef) return std::nullopt;
  const auto& g = georef->grid_to_crs;
  std::array<double, 4> b = {1e300, 1e300, -1e300, -1e300};
  for (double i : {-0.5, width - 0.5})
    for (double j : {-0.5, height - 0.5}) {
      const double x = g[0] + i * g[1] + j * g[2], y = g[3] + i * g[4] + j * g[5];
      b = {std::min(b[0], x), std::min(b[1], y), std::max(b[2], x), std::max(b[3], y)};
    }
  return b;
}

void Heightfield::finalize_stats() {
  if (paged) return;  // the paged loader's pass over the source filled them
  if (heights.empty()) {
    min_m = max_m = 0.0f;
    mean_m = 0.0;
    return;
  }
  float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
  double sum = 0.0;
  for (float h : heights) {
    lo = std::min(lo, h);
    hi = std::max(hi, h);
    sum += h;
  }
  min_m = lo;
  max_m = hi;
  mean_m = sum / double(heights.size());
}

}  // namespace ig::terrain
