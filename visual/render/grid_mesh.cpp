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

  glCreateBuffers(1, &vbo_);
  glNamedBufferStorage(vbo_, GLsizeiptr(verts.size() * sizeof(verts[0])), verts.data(), 0);
  glCreateBuffers(1, &ibo_);
  glNamedBufferStorage(ibo_, GLsizeiptr(idx.size() * sizeof(idx[0])), idx.data(), 0);
  glCreateVertexArrays(1, &vao_);
  glVertexArrayVertexBuffer(vao_, 0, vbo_, 0, 2 * sizeof(std::int16_t));
  glVertexArrayElementBuffer(vao_, ibo_);
  glEnableVertexArrayAttrib(vao_, 0);
  glVertexArrayAttribIFormat(vao_, 0, 2, GL_SHORT, 0);
  glVertexArrayAttribBinding(vao_, 0, 0);
}

GridMesh::~GridMesh() {
  glDeleteVertexArrays(1, &vao_);
  glDeleteBuffers(1, &vbo_);
  glDeleteBuffers(1, &ibo_);
}

void GridMesh::draw() const {
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
  gl::count_draw();
}

void GridMesh::draw_quadrant(int q) const {
  const GLsizei count = index_count_ / 4;
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT,
                 reinterpret_cast<const void*>(std::size_t(q) * std::size_t(count) * sizeof(std::uint32_t)));
  gl::count_draw();
}

}  // namespace ig::render
