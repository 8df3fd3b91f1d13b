#pragma once
// Height of the Level0 mesh surface at any point, for closing the step
// between Level1's edge and the coarser Level0 (the walls in
// twolevel_method.cpp). A uniform bucket grid over the DEM indexes the
// triangles, so a query tests a handful of them: about one triangle a
// bucket's area by default, 3.7 tested a query on the Table 2 flight (the
// walls ask once per Level1 edge sample every frame, each walk hinted with
// the triangle that held the last sample).

#include <vector>

#include "lod/roam_level0_mesh.h"

namespace ig::lod {

class Level0HeightQuery {
 public:
  // buckets_per_side 0: from the triangle count (its square root, 64 to 2048).
  Level0HeightQuery(const Level0Mesh& mesh, int dem_width, int dem_height, int buckets_per_side = 0);
  // Surface height at sample coordinates (i, j); outside the mesh: the
  // nearest bucket's best guess (the mesh covers the DEM, so only rounding).
  // hint: a triangle to try first, for queries walking along a line
  // (updated to the triangle that held this point; start with -1).
  double height_at(double i, double j, int* hint = nullptr) const;

 private:
  struct OnTriangle {
    bool valid = false;           // not degenerate
    double outside = 0, inside = 0;  // the most negative barycentric, negated (0 inside); the least one
    double height = 0;
  };
  OnTriangle evaluate(int triangle, double i, double j) const;
  const Level0Mesh& mesh_;
  int buckets_;
  double cell_x_, cell_y_;
  // Bucket k's triangles (ascending): bucket_tris_[bucket_start_[k] .. bucket_start_[k + 1]).
  std::vector<int> bucket_start_, bucket_tris_;
};

}  // namespace ig::lod
