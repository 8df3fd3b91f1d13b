#include "terrain/heightfield.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ig::terrain {

float Heightfield::at_clamped(int i, int j) const {
  i = std::clamp(i, 0, width - 1);
  j = std::clamp(j, 0, height - 1);
  return at(i, j);
}

double Heightfield::sample_bilinear(double x_m, double y_m) const {
  const double gx = std::clamp(x_m / spacing_x_m, 0.0, double(width - 1));
  const double gy = std::clamp(y_m / spacing_y_m, 0.0, double(height - 1));
  const int i = std::min(int(gx), std::max(width - 2, 0));
  const int j = std::min(int(gy), std::max(height - 2, 0));
  const double fx = gx - i, fy = gy - j;
  const double h00 = at_clamped(i, j), h10 = at_clamped(i + 1, j);
  const double h01 = at_clamped(i, j + 1), h11 = at_clamped(i + 1, j + 1);
  return (h00 * (1 - fx) + h10 * fx) * (1 - fy) + (h01 * (1 - fx) + h11 * fx) * fy;
}

double Heightfield::sample_surface(double x_m, double y_m) const {
  const double gx = std::clamp(x_m / spacing_x_m, 0.0, double(width - 1));
  const double gy = std::clamp(y_m / spacing_y_m, 0.0, double(height - 1));
  const int i = std::min(int(gx), std::max(width - 2, 0));
  const int j = std::min(int(gy), std::max(height - 2, 0));
  const double fx = gx - i, fy = gy - j;
  const double h00 = at_clamped(i, j), h10 = at_clamped(i + 1, j);
  const double h01 = at_clamped(i, j + 1), h11 = at_clamped(i + 1, j + 1);
  if (fx >= fy)  // triangle (i,j) (i+1,j) (i+1,j+1)
    return h00 + (h10 - h00) * fx + (h11 - h10) * fy;
  // triangle (i,j) (i+1,j+1) (i,j+1)
  return h00 + (h01 - h00) * fy + (h11 - h01) * fx;
}

void Heightfield::finalize_stats() {
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
