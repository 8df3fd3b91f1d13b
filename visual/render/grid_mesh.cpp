#include "render/grid_mesh.h"

#include <cstdint>
#include <vector>

#include "gl/work_counters.h"

namespace ig::render {

GridMesh::GridMesh(int n) : n_(n) {
  std::vector<std::int16_t> verts;
  verts.reserve(size_t(n + 1) * (n + 1) * 2);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      verts.push_back(std::int16_t(i));
      verts.push_back(std::int16_t(j));
    }
  std::vector<std::uint32_t> idx;
  idx.reserve(size_t(n) * n * 6);
  auto v = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  // Quarter by quarter when n is even (child order: SW, SE, NW, NE), so a
  // quarter is one contiguous index range (CDLOD draws single quarters).
  const int parts = n % 2 == 0 && n > 0 ? 2 : 1, h = n / parts;
  for (int q = 0; q < parts * parts; ++q)
    for (int j = (q / parts) * h; j < (q / parts + 1) * h; ++j)
      for (int i = (q % parts) * h; i < (q % parts + 1) * h; ++i) {
        // (i,j) (i+1,j) (i+1,j+1) and (i,j) (i+1,j+1) (i,j+1): counter-clockwise seen from above.
        idx.insert(idx.end(), {v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j), v(i + 1, j + 1), v(i, j + 1)});
      }
  index_count_ = GLsizei(idx.size());

  vbo_ = gl::create_buffer(verts);
  ibo_ = gl::create_buffer(idx);
  vao_ = gl::create_vertex_array();
  glVertexArrayVertexBuffer(vao_.id(), 0, vbo_.id(), 0, 2 * sizeof(std::int16_t));
  glVertexArrayElementBuffer(vao_.id(), ibo_.id());
  gl::vertex_attrib_int(vao_, 0, 2, GL_SHORT, 0, 0);
}

void GridMesh::draw() const {
  glBindVertexArray(vao_.id());
  glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
  gl::count_draw();
}

void GridMesh::draw_quadrant(int q) const {
  const GLsizei count = index_count_ / 4;
  glBindVertexArray(vao_.id());
  glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT,
                 reinterpret_cast<const void*>(std::size_t(q) * std::size_t(count) * sizeof(std::uint32_t)));
  gl::count_draw();
}

}  // namespace ig::render
