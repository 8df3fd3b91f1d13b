#include "stats/image_error.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace ig::stats {
namespace {

void check(const FrameImage& f, const char* which) {
  const std::size_t n = std::size_t(std::max(f.width, 0)) * std::size_t(std::max(f.height, 0));
  if (f.width <= 0 || f.height <= 0 || f.depth.size() != n || f.rgba.size() != 4 * n)
    throw std::invalid_argument(std::string("image_error: ") + which + " image is malformed (" +
                                std::to_string(f.width) + "x" + std::to_string(f.height) + ", " +
                                std::to_string(f.depth.size()) + " depth and " + std::to_string(f.rgba.size()) +
                                " colour values)");
}

// Topmost terrain row of column x, or height when the column is all sky.
int top_terrain_row(const FrameImage& f, int x) {
  for (int y = 0; y < f.height; ++y)
    if (f.terrain(x, y)) return y;
  return f.height;
}

// Grows a mask by `reach` pixels along one axis (dx, dy: the unit step).
std::vector<std::uint8_t> grow_mask(const std::vector<std::uint8_t>& mask, int w, int h, int dx, int dy, int reach) {
  std::vector<std::uint8_t> grown(mask.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t v = 0;
      for (int k = -reach; k <= reach && !v; ++k) {
        const int xx = x + k * dx, yy = y + k * dy;
        if (xx >= 0 && xx < w && yy >= 0 && yy < h) v = mask[std::size_t(yy) * w + xx];
      }
      grown[std::size_t(y) * w + x] = v;
    }
  return grown;
}

// Reference sky grown by `rows` rows and `cols` columns (separable box
// dilation): true where a reference-terrain pixel lies on a silhouette.
std::vector<std::uint8_t> near_sky_mask(const FrameImage& ref, int rows, int cols) {
  const int w = ref.width, h = ref.height;
  std::vector<std::uint8_t> sky(std::size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) sky[std::size_t(y) * w + x] = !ref.terrain(x, y);
  return grow_mask(grow_mask(sky, w, h, 1, 0, cols), w, h, 0, 1, rows);
}

}  // namespace

FrameImage read_frame_image(const gl::RenderTarget& target) {
  FrameImage f;
  f.width = target.width();
  f.height = target.height();
  f.rgba = target.read_rgba();
  f.depth = target.read_depth();
  return f;
}

double psnr_db_from_mse(double mse, double samples) {
  const double floor_mse = 1.0 / std::max(samples, 1.0);
  return 10.0 * std::log10(255.0 * 255.0 / std::max(mse, floor_mse));
}

ImageError image_error(const FrameImage& method, const FrameImage& ref, const render::Camera& camera,
                       const ImageErrorOptions& options) {
  check(method, "method");
  check(ref, "reference");
  if (method.width != ref.width || method.height != ref.height)
    throw std::invalid_argument("image_error: sizes differ (method " + std::to_string(method.width) + "x" +
                                std::to_string(method.height) + ", reference " + std::to_string(ref.width) + "x" +
                                std::to_string(ref.height) + ")");
  const int w = ref.width, h = ref.height;
  ImageError e;

  // Horizon, column by column.
  double sum = 0.0;
  std::vector<int> method_top(w);
  for (int x = 0; x < w; ++x) {
    const int yr = top_terrain_row(ref, x), ym = top_terrain_row(method, x);
    method_top[x] = ym;
    if (yr == h && ym == h) continue;
    ++e.horizon_columns;
    e.horizon_one_sided_columns += (yr == h) != (ym == h);
    const double off = std::abs(yr - ym);
    sum += off;
    e.horizon_max_px = std::max(e.horizon_max_px, off);
  }
  e.horizon_mean_px = e.horizon_columns ? sum / e.horizon_columns : 0.0;

  // Depth, coverage and colour, pixel by pixel.
  const auto near_sky = near_sky_mask(ref, std::max(options.silhouette_rows, 0), std::max(options.silhouette_cols, 0));
  std::vector<double> rel;
  double sq = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t p = std::size_t(y) * w + x;
      for (int c = 0; c < 3; ++c) {
        const double d = double(method.rgba[4 * p + c]) - double(ref.rgba[4 * p + c]);
        sq += d * d;
      }
      const float dm = method.depth[p];
      if (!std::isfinite(dm)) ++e.invalid_depth_pixels;
      const bool m_terrain = dm > 0.0f, r_terrain = ref.terrain(x, y);
      if (!r_terrain) {
        e.extra_terrain_pixels += m_terrain;
        continue;
      }
      ++e.reference_terrain_pixels;
      const bool interior = !near_sky[p];
      e.interior_pixels += interior;
      if (!m_terrain) {
        ++e.holes;
        e.enclosed_holes += y > method_top[x];
        if (interior) {
          ++e.interior_holes;
          if (options.list_interior_holes) e.interior_hole_pixels.push_back(p);
        }
        continue;
      }
      const double dr = camera.depth_to_view_distance(ref.depth[p]);
      const double dmv = camera.depth_to_view_distance(dm);
      if (dr > 0.0 && std::isfinite(dr) && std::isfinite(dmv)) rel.push_back(std::abs(dmv - dr) / dr);
    }
  e.depth_pixels = (long long)rel.size();
  if (!rel.empty()) {
    e.depth_rel_max = *std::max_element(rel.begin(), rel.end());
    // Nearest rank: the smallest value with at least 95 % of the pixels at or below it.
    const std::size_t k = std::size_t(std::ceil(0.95 * double(rel.size()))) - 1;
    std::nth_element(rel.begin(), rel.begin() + std::ptrdiff_t(k), rel.end());
    e.depth_rel_p95 = rel[k];
  }
  const double samples = 3.0 * double(w) * double(h);
  e.mse = sq / samples;
  e.psnr_db = psnr_db_from_mse(e.mse, samples);
  return e;
}

}  // namespace ig::stats
