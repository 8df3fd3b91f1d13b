#pragma once
// Exact ray casts against the rendered terrain surface.
//
// Frame: terrain-local metres (x east, y north, z up), the Heightfield's
// convention: sample (i, j) is at (i * spacing_x_m, j * spacing_y_m, at(i, j)).
// The surface is the one the renderer draws: each cell (quad) (i,j)-(i+1,j+1)
// is split into triangles (i,j),(i+1,j),(i+1,j+1) and (i,j),(i+1,j+1),(i,j+1)
// (see Heightfield::sample_surface). It covers only the DEM's footprint
// [0, extent_x_m] x [0, extent_y_m]; there are no skirts or walls, so a ray
// that passes outside the footprint, or under the terrain and out of a side,
// misses.
//
// Semantics (both functions):
//  * dir need not be normalised: it is normalised internally and t is in
//    metres along the normalised direction; point = origin + t * normalize(dir).
//  * Returns the hit with the smallest t in [0, max_t]. Crossings from below
//    the surface count as well as from above (a ray starting under the
//    terrain hits where it first comes out). An origin on the surface
//    (within 1e-9 m vertically, inside the footprint) gives t = 0 whatever
//    the direction; lift the origin for visibility or shadow rays.
//  * std::nullopt when nothing is hit (never a guess), and for invalid input:
//    zero-length dir, any NaN/inf in origin or dir, max_t NaN or negative, a
//    heightfield with fewer than 2 samples in x or y, or a spacing that is not
//    finite and > 0.
//  * Intersections are exact to double rounding: a watertight ray-triangle
//    test (ray-space shear + edge functions evaluated once per shared edge),
//    so a ray cannot slip between the two triangles of a quad or between
//    neighbouring cells, and touching an edge or vertex counts as a hit.
//    For a ray at angle a to the surface, t is defined to ~1e-16 / sin(a)
//    relative (rounding of the input alone moves it that much): 1e-12 at
//    1e-4 rad, 1e-8 at 1e-8 rad.
//    Ambiguous by nature: a ray lying exactly in a triangle's plane (e.g. a
//    horizontal ray exactly at the height of a flat area) gets no hit from
//    that triangle (it still hits where it meets a non-coplanar neighbour),
//    and a ray grazing exactly along an edge may or may not count it.
//  * cell_i, cell_j: the cell (quad) whose triangle was hit, 0 <= cell_i <
//    width - 1, 0 <= cell_j < height - 1. On a shared edge/vertex either
//    neighbour may be reported.

#include <limits>
#include <optional>

#include <glm/vec3.hpp>

#include "terrain/height_pyramid.h"
#include "terrain/heightfield.h"

namespace ig::terrain {

struct RayHit {
  double t;          // metres along the normalised direction
  glm::dvec3 point;  // origin + t * normalize(dir), terrain-local metres
  int cell_i, cell_j;
};

// Front-to-back traversal of the min/max pyramid; the pyramid must have been
// built from this heightfield (throws std::invalid_argument if its cell
// counts differ, or heights.size() != width * height). Thread-safe: no shared
// mutable state. About 1-4 us per ray on a 4097 x 4097 DEM (docs/ray-cast.md).
std::optional<RayHit> cast_ray(const Heightfield& hf, const HeightPyramid& pyramid,
                               glm::dvec3 origin, glm::dvec3 dir,
                               double max_t = std::numeric_limits<double>::infinity());

// The terrain as the renderer draws it for an eye at `centre` (x, y) with
// Earth curvature (terrain/earth_curvature.h): every sample (i, j) lowered by
// curvature_drop(distance from centre to the sample, radius_m), the triangles
// linear between the lowered samples. The ray is straight in that (the
// centre's tangent) frame; hit points are in it too (z lowered). radius_m
// <= 0: the flat surface (the same as the overloads without it).
struct Curvature {
  double centre_x = 0.0, centre_y = 0.0;
  double radius_m = 0.0;
};
std::optional<RayHit> cast_ray(const Heightfield& hf, const HeightPyramid& pyramid, glm::dvec3 origin,
                               glm::dvec3 dir, double max_t, const Curvature& curvature);

// Work done by one cast_ray, for tests and benchmarks.
struct RayCastStats {
  int nodes_tested = 0;  // pyramid nodes whose min/max box was tested against the ray
  int cells_tested = 0;  // cells whose two triangles were intersected
};
std::optional<RayHit> cast_ray(const Heightfield& hf, const HeightPyramid& pyramid,
                               glm::dvec3 origin, glm::dvec3 dir, double max_t,
                               RayCastStats& stats);

// Baseline without acceleration: walks every cell under the ray's 2D
// footprint (2D DDA) and tests its triangles with the same watertight test.
// Same conventions and results as cast_ray (up to the ambiguous cases above,
// and rounding when the ray passes within ~1e-10 of a cell corner). O(cells
// crossed): use it for cross-checks and benchmarks, not in production.
std::optional<RayHit> cast_ray_dda(const Heightfield& hf, glm::dvec3 origin, glm::dvec3 dir,
                                   double max_t = std::numeric_limits<double>::infinity());

}  // namespace ig::terrain
