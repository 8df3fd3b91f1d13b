#include "lod/terrain_floors.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <glm/common.hpp>

namespace ig::lod {

namespace {

// A polygon corner in sample coordinates with the plane's height there.
struct Corner {
  double x, y, z;
};
using Polygon = std::vector<Corner>;

// Keeps the part of `poly` where side(c) >= 0; side is linear, so the
// crossing point (and its height) interpolates linearly along the edge.
template <class Side>
void clip(Polygon& poly, Side side, Polygon& scratch) {
  scratch.clear();
  for (size_t k = 0; k < poly.size(); ++k) {
    const Corner& a = poly[k];
    const Corner& b = poly[(k + 1) % poly.size()];
    const double sa = side(a), sb = side(b);
    if (sa >= 0) scratch.push_back(a);
    if ((sa >= 0) != (sb >= 0)) {
      const double t = sa / (sa - sb);
      scratch.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)});
    }
  }
  poly.swap(scratch);
}

}  // namespace

TerrainFloors terrain_floors(const Level0Mesh& level0, const terrain::HeightPyramid& pyramid, int cell_level) {
  if (pyramid.empty()) return {};
  cell_level = std::clamp(cell_level, 0, pyramid.num_levels() - 1);
  TerrainFloors f;
  f.cell_samples = 1 << cell_level;
  f.nx = pyramid.level_width(cell_level);
  f.ny = pyramid.level_height(cell_level);
  f.grid_cells_x = pyramid.cells_x();
  f.grid_cells_y = pyramid.cells_y();
  f.floor_m.resize(size_t(f.nx) * f.ny);
  f.chord_samples.assign(size_t(f.nx) * f.ny, float(std::sqrt(2.0)));  // the DEM's grid cells
  for (int j = 0; j < f.ny; ++j)
    for (int i = 0; i < f.nx; ++i) f.floor_m[size_t(j) * f.nx + i] = pyramid.node(cell_level, i, j).lo;

  const int cells_x = pyramid.cells_x(), cells_y = pyramid.cells_y();
  const int s = f.cell_samples;
  Polygon poly, scratch;
  for (size_t t = 0; t + 2 < level0.indices.size(); t += 3) {
    std::array<Corner, 3> tri;
    glm::ivec2 lo(1 << 30), hi(-(1 << 30));
    for (int k = 0; k < 3; ++k) {
      const auto v = level0.indices[t + k];
      const glm::ivec2 smp = level0.samples[v];
      tri[k] = {double(smp.x), double(smp.y), double(level0.positions[v].z)};
      lo = glm::min(lo, smp);
      hi = glm::max(hi, smp);
    }
    // Cells the triangle's box touches (a vertex on a cell edge touches both sides).
    const int i0 = std::max(0, (lo.x - 1) / s), i1 = std::min(f.nx - 1, hi.x / s);
    const int j0 = std::max(0, (lo.y - 1) / s), j1 = std::min(f.ny - 1, hi.y / s);
    const auto chord = float(std::hypot(double(hi.x - lo.x), double(hi.y - lo.y)));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        float& c = f.chord_samples[size_t(j) * f.nx + i];
        c = std::max(c, chord);
        const double x0 = i * s, x1 = std::min((i + 1) * s, cells_x), y0 = j * s, y1 = std::min((j + 1) * s, cells_y);
        poly.assign(tri.begin(), tri.end());
        clip(poly, [&](const Corner& c) { return c.x - x0; }, scratch);
        clip(poly, [&](const Corner& c) { return x1 - c.x; }, scratch);
        clip(poly, [&](const Corner& c) { return c.y - y0; }, scratch);
        clip(poly, [&](const Corner& c) { return y1 - c.y; }, scratch);
        float& floor = f.floor_m[size_t(j) * f.nx + i];
        for (const Corner& c : poly) floor = std::min(floor, float(c.z));
      }
  }
  // Float rounding of the interpolated corners: keep the floor safely under.
  for (auto& v : f.floor_m) v -= 0.01f + 1e-6f * std::abs(v);
  return f;
}

}  // namespace ig::lod
