#include "gl/gl_objects.h"

namespace ig::gl {

namespace detail {
void destroy(ObjectKind kind, GLuint id) {
  switch (kind) {
    case ObjectKind::Buffer: glDeleteBuffers(1, &id); break;
    case ObjectKind::VertexArray: glDeleteVertexArrays(1, &id); break;
    case ObjectKind::Texture: glDeleteTextures(1, &id); break;
    case ObjectKind::Framebuffer: glDeleteFramebuffers(1, &id); break;
    case ObjectKind::Query: glDeleteQueries(1, &id); break;
  }
}
}  // namespace detail

Buffer create_buffer(const void* data, std::size_t bytes, GLbitfield flags) {
  Buffer b = create_buffer();
  // Zero-size storage is an error in GL: keep one byte so empty meshes stay valid objects.
  glNamedBufferStorage(b.id(), GLsizeiptr(bytes > 0 ? bytes : 1), bytes > 0 ? data : nullptr, flags);
  return b;
}

Buffer create_buffer() {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  return Buffer(id);
}

VertexArray create_vertex_array() {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  return VertexArray(id);
}

Texture create_texture(GLenum target) {
  GLuint id = 0;
  glCreateTextures(target, 1, &id);
  return Texture(id);
}

Framebuffer create_framebuffer() {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  return Framebuffer(id);
}

Query create_query() {
  GLuint id = 0;
  glGenQueries(1, &id);
  return Query(id);
}

void vertex_attrib_int(const VertexArray& vao, GLuint index, GLint size, GLenum type, GLuint offset, GLuint binding) {
  glEnableVertexArrayAttrib(vao.id(), index);
  glVertexArrayAttribIFormat(vao.id(), index, size, type, offset);
  glVertexArrayAttribBinding(vao.id(), index, binding);
}

void vertex_attrib_float(const VertexArray& vao, GLuint index, GLint size, GLenum type, GLuint offset,
                         GLuint binding) {
  glEnableVertexArrayAttrib(vao.id(), index);
  glVertexArrayAttribFormat(vao.id(), index, size, type, GL_FALSE, offset);
  glVertexArrayAttribBinding(vao.id(), index, binding);
}

}  // namespace ig::gl
