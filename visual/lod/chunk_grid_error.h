#pragma once
// Geometric error of a coarse terrain mesh against the full-resolution DEM,
// shared by the grid-based baselines (geomipmap, chunked, cdlod): the largest
// vertical distance, over every DEM sample the mesh covers, between the
// sample's height and the mesh's height above it. Vertices are DEM samples
// at integer offsets from an origin, clamped onto the DEM exactly as the
// vertex shaders clamp them (so a grid reaching past the DEM's edge folds its
// outer quads onto the edge column/row, and the error is that of the folded
// mesh, the one drawn).

#include <vector>

#include <glm/vec2.hpp>

#include "terrain/heightfield.h"

namespace ig::lod {

// Height range of the samples in [i0, i0 + n_i] x [j0, j0 + n_j] (clamped to
// the DEM): the vertical extent of a block's bounding box.
struct HeightRange {
  float min_m = 0.0f, max_m = 0.0f;
};
HeightRange sample_height_range(const terrain::Heightfield& hf, int i0, int j0, int n_i, int n_j);

// Regular grid of quads x quads quads, `stride` samples per quad, origin
// (i0, j0), split along the (i,j)-(i+1,j+1) diagonal (grid_mesh.h).
float grid_max_error(const terrain::Heightfield& hf, int i0, int j0, int quads, int stride);
// Triangles of that grid with non-zero area once clamped onto the DEM (the
// ones counted as drawn; the others are folded onto the DEM's edge).
int grid_triangle_count(const terrain::Heightfield& hf, int i0, int j0, int quads, int stride);

// Any triangle list: three corners per triangle, integer sample offsets from
// (i0, j0). Degenerate (zero-area after clamping) triangles cover nothing.
float triangles_max_error(const terrain::Heightfield& hf, int i0, int j0, const std::vector<glm::ivec2>& corners);
int triangles_nondegenerate_count(const terrain::Heightfield& hf, int i0, int j0,
                                  const std::vector<glm::ivec2>& corners);

}  // namespace ig::lod
