#pragma once
// Precomputed ROAM error bounds ("wedgie thicknesses", Duchaineau et al.
// 1997) for every bintree diamond over a patch grid, one float per sample:
// entry (i, j) belongs to the diamond whose hypotenuse midpoint is sample
// (i, j).
//
// The bound is nested and additive, as in the paper:
//   e(D) = |h(mid) - (h(a) + h(b)) / 2| + max(e(children of D))
// so each triangle's plane stays within e of the surface everywhere over the
// triangle (not only at the sampled midpoints). The surface is the
// reference's (render/grid_mesh): the finest bintree triangles, which split
// some cells along the other diagonal, carry that difference
// (roam_surface.h), so a full-resolution bintree still reports it.
//
// Diamond layout (patch side P, all patches split along (x0,y0)-(x1,y1)):
// for half-hypotenuse h = 1, 2, ..., P/2, axis diamonds (hypotenuse 2h,
// horizontal at i = h mod 2h, j = 0 mod 2h; vertical transposed) and square
// diamonds of side 2h centred at (h, h) mod 2h, whose hypotenuse is the main
// diagonal when ((i-h)/2h + (j-h)/2h) is even, and always for the patches'
// own root diamonds (2h = P).

#include <cstddef>
#include <vector>

#include "lod/roam_patch_grid.h"
#include "terrain/heightfield.h"

namespace ig::lod {

struct RoamWedgieGrid {
  int side_x = 0, side_y = 0;  // padded samples: grid.padded_x() + 1, grid.padded_y() + 1
  std::vector<float> error;    // metres, row-major
  float at(int i, int j) const { return error[std::size_t(j) * side_x + i]; }
};

RoamWedgieGrid compute_roam_wedgies(const terrain::Heightfield& hf, const PatchGrid& grid);

}  // namespace ig::lod
