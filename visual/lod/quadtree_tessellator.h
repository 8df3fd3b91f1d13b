#pragma once
// Per-frame restricted quadtree LOD (Röttger et al. 1998, as in the seed
// articles 002/003; docs/baselines.md, "quadtree"):
//
//   1. Top-down from the root nodes, a node in view is split when
//        f = L / (d * C1 * max(C2 * DHmax, 1)) < 1
//      L = distance from the eye to the node's centre (on the surface),
//      d = node edge length (metres), DHmax = its propagated roughness
//      (quadtree_nodes.h) in sample spacings (the seed works in grid units),
//      so C1 and C2 are pure numbers. Nodes outside the view volume are not
//      split.
//   2. Restriction: any split node whose same-size neighbour does not exist
//      (its parent is a leaf) forces that parent to split, recursively, so
//      edge-adjacent leaves differ by at most one level whatever the camera
//      (the roughness propagation makes this rare; the count is reported).
//   3. Each leaf in view is drawn as a triangle fan around its centre; the
//      midpoint of an edge is left out where the neighbour across it is
//      coarser (its same-size neighbour does not exist), which removes the
//      T-junction there. Nodes crossing the DEM's east/north edge are
//      clipped to it (roam_patch_grid.h).
//
// The error bound of a drawn leaf: fan_error + the deviations of its dropped
// midpoints (twice that when clipped), over the distance from the eye to its
// box. Output: triangles as DEM sample indices (3 vertices each,
// counter-clockwise seen from above), drawn by shaders/level0.vert. No GL here.

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/gtc/type_precision.hpp>

#include "lod/quadtree_nodes.h"
#include "lod/roam_surface.h"
#include "lod/roam_patch_grid.h"
#include "terrain/heightfield.h"

namespace ig::lod {

struct QuadtreeFrameStats {
  long long evaluated = 0;       // nodes whose f was computed
  long long splits = 0;          // nodes split by f < 1
  long long forced_splits = 0;   // nodes split by the restriction
  long long leaves = 0;          // leaves drawn (in view, inside the DEM)
  long long culled = 0;          // leaves left out as outside the view
  long long triangles = 0;       // triangles output (after clipping)
  double max_error_ratio = 0.0;  // largest error / distance (radians) over drawn leaves
};

// One frame's mesh, as a value the renderer consumes.
struct QuadtreeSelection {
  std::vector<glm::u16vec2> vertices;  // triangles as DEM sample indices, 3 per triangle
  QuadtreeFrameStats stats;
};

class QuadtreeTessellator {
 public:
  // Throws std::invalid_argument for grids smaller than 2 x 2 or wider or
  // taller than 65536 samples (vertices are 16-bit sample indices).
  explicit QuadtreeTessellator(const terrain::Heightfield& hf);

  // Builds the mesh for an eye at `eye` (terrain-local metres). Distances
  // below min_distance_m (the near plane) count as that in the error bound.
  // `recycled` (last frame's selection) lends its memory. Throws
  // std::invalid_argument unless c1 > 0 and c2 >= 0 (finite).
  QuadtreeSelection select(const glm::dvec3& eye, double c1, double c2, const BoxInView& in_view = {},
                           double min_distance_m = 0.5, QuadtreeSelection recycled = {});

  const QuadtreeNodes& nodes() const { return nodes_; }
  double build_ms() const { return build_ms_; }
  // Level of the leaf covering cell (cx, cy) after the last select (0 =
  // finest, 3 x 3 samples), or -1 outside the patch grid. For tests.
  int leaf_level(int cx, int cy) const;

 private:
  struct NodeRef {
    int k, a, b;
  };
  bool exists(int k, int a, int b) const;
  bool inside_dem(int k, int a, int b) const;
  void evaluate(int k, int a, int b);
  void force_split(int k, int a, int b);
  void restrict_levels();
  void emit(int k, int a, int b);
  void emit_leaf(int k, int a, int b);

  const terrain::Heightfield& hf_;
  PaddedHeights heights_;
  double inv_spacing_;  // 1 / sqrt(spacing_x * spacing_y)
  QuadtreeNodes nodes_;
  double build_ms_ = 0.0;

  // Per frame.
  glm::dvec3 eye_{0.0};
  double c1_ = 1.0, c2_ = 0.0, min_distance_ = 0.5;
  const BoxInView* in_view_ = nullptr;
  std::vector<std::uint8_t> split_;  // per node
  std::vector<NodeRef> split_list_;  // the split nodes (worklist of the restriction; cleared next frame)
  QuadtreeSelection sel_;  // handed out at the end of select
};

}  // namespace ig::lod
