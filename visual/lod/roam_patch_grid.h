#pragma once
// How the view-dependent LODs (ROAM, quadtree) lay their hierarchies over a
// DEM of any size: a grid of square power-of-two patches anchored at sample
// (0, 0), covering at least the DEM. Patches past the DEM's east/north edge
// hang over it; heights there are the nearest edge sample (clamped), nothing
// wholly outside the DEM is refined or drawn, and triangles crossing the
// edge are clipped to it (clip_to_dem). The hierarchies' edges are
// axis-aligned or at 45 degrees, so every clip point is a DEM sample and the
// output covers exactly the DEM.

#include <functional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ig::lod {

// Whether an eye-relative box (metres) may be in view; empty: everything is.
using BoxInView = std::function<bool(const glm::dvec3& lo, const glm::dvec3& hi)>;

struct PatchGrid {
  int patch = 1;       // patch side in cells (a power of two)
  int nx = 0, ny = 0;  // patches west -> east, south -> north
  int lim_x = 0, lim_y = 0;  // last DEM sample index (width - 1, height - 1)
  int padded_x() const { return nx * patch; }  // covered cells
  int padded_y() const { return ny * patch; }
  // Whether the cell-aligned box [x0, x1] x [y0, y1] overlaps the DEM with non-zero area.
  bool overlaps_dem(int x0, int y0) const { return x0 < lim_x && y0 < lim_y; }
  // Whether the box reaches past the DEM's east or north edge.
  bool crosses_edge(int x1, int y1) const { return x1 > lim_x || y1 > lim_y; }
};

// Patch side: the largest power of two <= the DEM's shorter side in cells,
// within [min_patch, max_patch], halved (down to 64) while the padded area
// exceeds the DEM's by more than 30 %. Throws std::invalid_argument for
// grids smaller than 2 x 2 samples.
PatchGrid make_patch_grid(int width, int height, int min_patch = 1, int max_patch = 1024);

// Clips the triangle (a, b, c) (integer sample coordinates, edges
// axis-aligned or at 45 degrees, coordinates >= 0) to x <= lim_x, y <= lim_y
// and fans the result from its first vertex: up to 3 triangles, same winding,
// degenerate ones dropped. Returns how many were written to out.
int clip_to_dem(const glm::ivec2& a, const glm::ivec2& b, const glm::ivec2& c, int lim_x, int lim_y,
                glm::ivec2 out[3][3]);

}  // namespace ig::lod
