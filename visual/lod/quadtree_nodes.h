#pragma once
// Precomputed per-node data of the restricted quadtree LOD (docs/baselines.md,
// "quadtree"; Röttger et al. 1998 and the seed articles 002/003).
//
// Nodes are squares of side 2h samples (h = 1, 2, 4, ..., patch/2) tiling a
// patch grid (roam_patch_grid.h; each patch is one root node); node (k, a, b)
// has half-size h = 2^k and centre ((2a+1)h, (2b+1)h). A node is drawn as a
// fan around its centre through its 4 corners and 4 edge midpoints.
//
// roughness ("DHmax"): the seed's surface roughness, the largest of the six
//   midpoint deviations |h(mid) - (h(a) + h(b)) / 2| of the node's 4 edges
//   and 2 diagonals, then raised bottom-up to at least the roughness of its
//   4 children (Röttger's parent >= child propagation) and of the 8
//   half-size nodes just outside its edges (the seed's rule, so that a node
//   splits whenever a finer neighbour's parent does and adjacent leaves
//   differ by at most one level).
// fan_error: a bound on |full 9-vertex fan - reference surface| over the
//   node, nested and additive like ROAM's wedgies: the largest child bound
//   plus the largest deviation of the children's new vertices from this
//   node's fan; at h = 1 the difference between the fan's cell diagonals and
//   the reference's (roam_surface.h).
// lo, hi: min / max sample height over the node (heights past the DEM's
//   edge are the edge's), which bound every surface drawn over it.

#include <cstddef>
#include <vector>

#include "lod/roam_patch_grid.h"
#include "terrain/heightfield.h"

namespace ig::lod {

struct QuadtreeNodes {
  PatchGrid grid;                // root nodes = patches (side >= 2)
  int levels = 0;                // k = 0 .. levels-1; the roots are level levels-1
  std::vector<int> nx, ny;       // nodes per level
  std::vector<std::size_t> offset;
  std::vector<float> roughness;  // metres
  std::vector<float> fan_error;  // metres
  std::vector<float> lo, hi;     // metres
  std::size_t index(int k, int a, int b) const { return offset[k] + std::size_t(b) * nx[k] + a; }
  std::size_t count() const { return roughness.size(); }
};

// Throws std::invalid_argument for grids smaller than 2 x 2 samples.
QuadtreeNodes compute_quadtree_nodes(const terrain::Heightfield& hf);

}  // namespace ig::lod
