#pragma once
// Triangles rebuilt on the CPU every frame (the ROAM and quadtree baselines'
// DEM sample indices, u16vec2 per vertex, read as ivec2 at location 0):
// uploaded once per frame into an orphaned stream buffer and drawn.

#include <vector>

#include <glm/gtc/type_precision.hpp>

#include "gl/gl_objects.h"

namespace ig::gl {

class StreamVertices {
 public:
  StreamVertices();
  // Uploads `vertices` (3 per triangle) and draws them with the bound program.
  void draw(const std::vector<glm::u16vec2>& vertices);

 private:
  VertexArray vao_;
  Buffer vbo_;
  GLsizeiptr capacity_ = 0;  // bytes allocated for the buffer
};

}  // namespace ig::gl
