#include "gl/stream_vertices.h"

#include <algorithm>

#include "gl/draw_pacing.h"
#include "gl/work_counters.h"

namespace ig::gl {

StreamVertices::StreamVertices() : vao_(create_vertex_array()), vbo_(create_buffer()) {
  glVertexArrayVertexBuffer(vao_.id(), 0, vbo_.id(), 0, sizeof(glm::u16vec2));
  vertex_attrib_int(vao_, 0, 2, GL_UNSIGNED_SHORT, 0, 0);  // -> ivec2 a_sample
}

void StreamVertices::draw(const std::vector<glm::u16vec2>& vertices) {
  if (vertices.empty()) return;
  const GLsizeiptr bytes = GLsizeiptr(vertices.size() * sizeof(glm::u16vec2));
  // Orphan the old storage (the GPU may still read it) rather than wait for
  // it; grow geometrically so steady frames never reallocate on our side.
  if (bytes > capacity_) capacity_ = std::max<GLsizeiptr>(bytes + bytes / 2, 1 << 16);
  glNamedBufferData(vbo_.id(), capacity_, nullptr, GL_STREAM_DRAW);
  glNamedBufferSubData(vbo_.id(), 0, bytes, vertices.data());
  count_upload(std::uint64_t(bytes));
  glBindVertexArray(vao_.id());
  draw_triangle_list(0, GLsizei(vertices.size()));
}

}  // namespace ig::gl
