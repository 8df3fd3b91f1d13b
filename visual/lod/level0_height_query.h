#pragma once
// Height of the Level0 mesh surface at any point, for closing the step
// between Level1's edge and the coarser Level0 (the walls in
// twolevel_method.cpp). A uniform bucket grid over the DEM indexes the
// triangles, so a query tests a handful of them.

#include <vector>

#include "lod/roam_level0_mesh.h"

namespace ig::lod {

class Level0HeightQuery {
 public:
  Level0HeightQuery(const Level0Mesh& mesh, int dem_width, int dem_height, int buckets_per_side = 64);
  // Surface height at sample coordinates (i, j); outside the mesh: the
  // nearest bucket's best guess (the mesh covers the DEM, so only rounding).
  double height_at(double i, double j) const;

 private:
  const Level0Mesh& mesh_;
  int buckets_;
  double cell_x_, cell_y_;
  std::vector<std::vector<int>> bucket_tris_;
};

}  // namespace ig::lod
