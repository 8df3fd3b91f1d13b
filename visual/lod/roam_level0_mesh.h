#pragma once
// Level0 of the two-level terrain: a static, view-independent ROAM mesh over
// the whole DEM, built once at load time (see docs/level0.md).
//
// A binary triangle tree covers the enclosing (2^n+1)-sided square of samples
// (the DEM sits at its south-west corner). Each diamond's error (|height at the
// hypotenuse midpoint - mean of the hypotenuse end heights|, maximised over all
// descendant diamonds) is precomputed into one float per sample (the diamond's
// hypotenuse midpoint). Refinement is greedy, largest error first, with forced
// splits of base neighbours, so the mesh is crack-free by construction. It
// stops at the triangle budget or when the largest remaining error is <= the
// error target.
//
// Non-(2^n+1) DEMs: heights outside the DEM are the nearest edge sample, but
// diamonds whose midpoint lies outside the DEM have zero local error, triangles
// wholly outside the DEM are dropped and triangles crossing the DEM border are
// clipped to it (the tree's edges are axis-aligned or at 45 degrees, so every
// clip point is a DEM sample). The output therefore covers exactly the DEM.

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "terrain/heightfield.h"

namespace ig::lod {

struct Level0Options {
  // Stop once the mesh has at least this many triangles (overlapping the
  // DEM). Forced splits and border clipping may overshoot it slightly.
  int triangle_budget = 2048;
  // Stop once the largest error of any splittable leaf is <= this (metres).
  double error_target_m = 0.0;
  // Earth radius the scene is drawn with (0 = flat). The drop is applied per
  // vertex, so a flat triangle with hypotenuse L sags up to L^2 / (8 R) below
  // the sphere between its vertices: added to each triangle's error so flat
  // ground (error 0) still refines where the curve needs it.
  double earth_radius_m = 0.0;
  // Error of a triangle measured over the whole triangle: the largest
  // vertical distance between its plane and any DEM sample it covers (so
  // max_error_m bounds every sample), instead of the nested error at
  // hypotenuse midpoints (the paper's ROAM). Slower to build (each
  // considered triangle visits its samples).
  bool whole_triangle_error = false;
};

struct Level0Mesh {
  std::vector<glm::vec3> positions;  // x, y metres (terrain-local), z height
  std::vector<glm::ivec2> samples;   // DEM sample index (i, j) of each vertex
  std::vector<std::uint32_t> indices;  // triangles, CCW seen from above (+z)
  double max_error_m = 0.0;  // largest error of any unsplit (splittable) triangle
  int triangle_count = 0;    // indices.size() / 3
  double build_ms = 0.0;     // wall time of build_level0_mesh
};

// Builds the Level0 mesh. Throws std::invalid_argument for grids smaller than
// 2x2 or whose heights vector does not match width*height.
Level0Mesh build_level0_mesh(const terrain::Heightfield& hf, const Level0Options& opts = {});

// Diamond error grid used by build_level0_mesh, exposed for tests: side N =
// 2^n+1 >= max(width, height), row-major, entry (i, j) = error of the diamond
// whose hypotenuse midpoint is sample (i, j) (0 for corners / outside).
struct Level0ErrorGrid {
  int side = 0;
  std::vector<float> error;
};
Level0ErrorGrid compute_level0_errors(const terrain::Heightfield& hf);

}  // namespace ig::lod
