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

namespace {
// A new GL name from `make` (one of the glCreate*/glGen* calls), owned by a handle.
template <class Handle, class Make>
Handle named(Make make) {
  GLuint id = 0;
  make(&id);
  return Handle(id);
}
}  // namespace

Buffer create_buffer() {
  return named<Buffer>([&](GLuint* id) { glCreateBuffers(1, id); });
}

VertexArray create_vertex_array() {
  return named<VertexArray>([&](GLuint* id) { glCreateVertexArrays(1, id); });
}

Texture create_texture(GLenum target) {
  return named<Texture>([&](GLuint* id) { glCreateTextures(target, 1, id); });
}

Framebuffer create_framebuffer() {
  return named<Framebuffer>([&](GLuint* id) { glCreateFramebuffers(1, id); });
}

Query create_query() {
  return named<Query>([&](GLuint* id) { glGenQueries(1, id); });
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
