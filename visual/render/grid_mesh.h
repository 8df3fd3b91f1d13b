#pragma once
// A static (n+1) x (n+1) vertex grid of integer sample offsets with its index
// buffer: the one mesh every grid-based pass draws many times (placed by
// uniforms, displaced by the height texture). Quads split along the
// (i,j)-(i+1,j+1) diagonal, the convention the ray cast and
// Heightfield::sample_surface() also use.

#include "gl/gl_objects.h"

namespace ig::render {

class GridMesh {
 public:
  explicit GridMesh(int quads_per_side);

  int quads_per_side() const { return n_; }
  GLsizei index_count() const { return index_count_; }
  // Draw the whole grid (the caller has set the program and its uniforms).
  void draw() const;
  // Draw one quarter, q = 0 SW, 1 SE, 2 NW, 3 NE (n even only).
  void draw_quadrant(int q) const;

 private:
  int n_;
  gl::VertexArray vao_;
  gl::Buffer vbo_, ibo_;
  GLsizei index_count_ = 0;
};

}  // namespace ig::render
