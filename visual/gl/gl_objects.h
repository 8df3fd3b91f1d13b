#pragma once
// GL objects behind small move-only handles: created (DSA) by the factories
// below, deleted when the handle goes. Passes and LOD methods hold these,
// never raw GL names, so nothing leaks on a rebuild or an exception.

#include <epoxy/gl.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace ig::gl {

enum class ObjectKind { Buffer, VertexArray, Texture, Framebuffer, Query };

namespace detail {
void destroy(ObjectKind kind, GLuint id);
}

template <ObjectKind K>
class Object {
 public:
  Object() = default;
  explicit Object(GLuint adopted) : id_(adopted) {}
  ~Object() { reset(); }
  Object(Object&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Object& operator=(Object&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_) detail::destroy(K, id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

using Buffer = Object<ObjectKind::Buffer>;
using VertexArray = Object<ObjectKind::VertexArray>;
using Texture = Object<ObjectKind::Texture>;
using Framebuffer = Object<ObjectKind::Framebuffer>;
using Query = Object<ObjectKind::Query>;

// A buffer with immutable storage of `bytes` (glNamedBufferStorage flags;
// GL_DYNAMIC_STORAGE_BIT to update it with glNamedBufferSubData).
Buffer create_buffer(const void* data, std::size_t bytes, GLbitfield flags = 0);
template <class T>
Buffer create_buffer(const std::vector<T>& v, GLbitfield flags = 0) {
  return create_buffer(v.data(), v.size() * sizeof(T), flags);
}
// A buffer without storage yet (glNamedBufferData later, e.g. streamed data).
Buffer create_buffer();
VertexArray create_vertex_array();
Texture create_texture(GLenum target);
Framebuffer create_framebuffer();
// glGenQueries, not glCreateQueries: Mesa 22.3 refuses the pipeline
// statistics targets in glCreateQueries (GL_INVALID_ENUM); a generated name
// takes its target at its first glBeginQuery.
Query create_query();

// Vertex layout: attribute `index` read from binding `binding` at `offset`,
// as integers (ivec, GL_SHORT / GL_INT ...) or as floats.
void vertex_attrib_int(const VertexArray& vao, GLuint index, GLint size, GLenum type, GLuint offset, GLuint binding);
void vertex_attrib_float(const VertexArray& vao, GLuint index, GLint size, GLenum type, GLuint offset,
                         GLuint binding);

}  // namespace ig::gl
