#include "gl/static_mesh.h"

#include "gl/draw_pacing.h"

namespace ig::gl {

StaticMesh::StaticMesh(const std::vector<std::int16_t>& vertices, int stride, const std::vector<Attribute>& attributes)
    : vao_(create_vertex_array()), vbo_(create_buffer(vertices)) {
  glVertexArrayVertexBuffer(vao_.id(), 0, vbo_.id(), 0, GLsizei(stride * sizeof(std::int16_t)));
  for (std::size_t k = 0; k < attributes.size(); ++k)
    vertex_attrib_int(vao_, GLuint(k), attributes[k].components, GL_SHORT,
                      GLuint(attributes[k].first * sizeof(std::int16_t)), 0);
}

int StaticMesh::add_indices(const std::vector<std::uint32_t>& indices) {
  lists_.push_back({create_buffer(indices), int(indices.size()), true});
  return int(lists_.size()) - 1;
}

int StaticMesh::add_indices(const std::vector<std::uint16_t>& indices) {
  lists_.push_back({create_buffer(indices), int(indices.size()), false});
  return int(lists_.size()) - 1;
}

void StaticMesh::draw(int list, int first, int count) const {
  const IndexList& l = lists_[static_cast<std::size_t>(list)];
  glVertexArrayElementBuffer(vao_.id(), l.buffer.id());
  glBindVertexArray(vao_.id());
  draw_indexed_triangles(l.wide ? GL_UNSIGNED_INT : GL_UNSIGNED_SHORT, first, count);
}

}  // namespace ig::gl
