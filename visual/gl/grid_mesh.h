#pragma once
// A static (n+1) x (n+1) vertex grid of integer sample offsets with its index
// buffer: the one mesh every grid-based pass draws many times (placed by
// uniforms, displaced by the height texture). Quads split along the
// (i,j)-(i+1,j+1) diagonal, the convention the ray cast and
// Heightfield::sample_surface() also use.

#include "gl/static_mesh.h"

namespace ig::gl {

class GridMesh {
 public:
  explicit GridMesh(int quads_per_side);

  int quads_per_side() const { return n_; }
  int index_count() const { return mesh_.index_count(list_); }
  // Draw the whole grid (the caller has set the program and its uniforms).
  void draw() const { mesh_.draw(list_); }
  // Draw one quarter, q = 0 SW, 1 SE, 2 NW, 3 NE (n even only).
  void draw_quadrant(int q) const;

 private:
  int n_;
  StaticMesh mesh_;
  int list_ = 0;
};

}  // namespace ig::gl
