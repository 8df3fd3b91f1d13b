#include "lod/roam_patch_grid.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace ig::lod {

PatchGrid make_patch_grid(int width, int height, int min_patch, int max_patch) {
  if (width < 2 || height < 2)
    throw std::invalid_argument("patch grid: the DEM must have at least 2 x 2 samples (got " +
                                std::to_string(width) + " x " + std::to_string(height) + ")");
  PatchGrid g;
  g.lim_x = width - 1;
  g.lim_y = height - 1;
  const int shorter = std::min(g.lim_x, g.lim_y);
  int p = 1;
  while (p * 2 <= shorter && p * 2 <= max_patch) p *= 2;
  p = std::max(p, min_patch);
  auto padded_area = [&](int s) {
    return double((g.lim_x + s - 1) / s * s) * double((g.lim_y + s - 1) / s * s);
  };
  // Overhang costs memory (the error grids cover it) but not triangles.
  while (p > 64 && p / 2 >= min_patch && padded_area(p) > 1.3 * double(g.lim_x) * g.lim_y) p /= 2;
  g.patch = p;
  g.nx = (g.lim_x + p - 1) / p;
  g.ny = (g.lim_y + p - 1) / p;
  return g;
}

namespace {

// Clips a polygon of integer points to coordinate `ax` <= lim. Cut points are
// exact integers because every edge is axis-aligned or at 45 degrees.
int clip_le(const glm::ivec2* in, int n, int ax, int lim, glm::ivec2* out) {
  int m = 0;
  for (int k = 0; k < n; ++k) {
    const glm::ivec2 p = in[k], q = in[(k + 1) % n];
    const bool pin = p[ax] <= lim, qin = q[ax] <= lim;
    if (pin) out[m++] = p;
    if (pin != qin && p[ax] != lim && q[ax] != lim) {
      const int o = 1 - ax;
      glm::ivec2 c;
      c[ax] = lim;
      c[o] = p[o] + (q[o] - p[o]) * (lim - p[ax]) / (q[ax] - p[ax]);
      out[m++] = c;
    }
  }
  // Drop repeated points (including around the wrap).
  int r = 0;
  for (int k = 0; k < m; ++k)
    if (r == 0 || out[r - 1] != out[k]) out[r++] = out[k];
  while (r > 1 && out[0] == out[r - 1]) --r;
  return r;
}

}  // namespace

int clip_to_dem(const glm::ivec2& a, const glm::ivec2& b, const glm::ivec2& c, int lim_x, int lim_y,
                glm::ivec2 out[3][3]) {
  // A triangle clipped by two half-planes has at most 5 corners.
  glm::ivec2 p0[3] = {a, b, c}, p1[8], p2[8];
  int n = clip_le(p0, 3, 0, lim_x, p1);
  if (n >= 3) n = clip_le(p1, n, 1, lim_y, p2);
  int count = 0;
  for (int k = 1; n >= 3 && k + 1 < n; ++k) {
    const glm::ivec2 u = p2[k] - p2[0], v = p2[k + 1] - p2[0];
    if (std::int64_t(u.x) * v.y - std::int64_t(u.y) * v.x == 0) continue;
    out[count][0] = p2[0];
    out[count][1] = p2[k];
    out[count][2] = p2[k + 1];
    ++count;
  }
  return count;
}

}  // namespace ig::lod
