#include "gl/window_storage.h"

#include <cstdint>
#include <vector>

#include "gl/gl_context.h"

namespace ig::gl {

WindowStorage::WindowStorage(int width, int height, const TexelFormat& format, const std::string& what)
    : format_(format) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (width > max_size || height > max_size)
    throw GlError(what + " " + std::to_string(width) + "x" + std::to_string(height) +
                  " exceeds the GL texture limit " + std::to_string(max_size));
  tex_ = create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(tex_.id(), 1, format_.internal_format, width, height);
  glTextureParameteri(tex_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(tex_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // Wrap-around addressing: the texel after the last is the first, which
  // holds the next texel of the window in the grid.
  glTextureParameteri(tex_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(tex_.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
}

void WindowStorage::upload(int x, int y, int w, int h, const void* data, int row_length) const {
  glPixelStorei(GL_UNPACK_ALIGNMENT, format_.unpack_alignment);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, row_length);
  glTextureSubImage2D(tex_.id(), 0, x, y, w, h, format_.format, format_.type, data);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
}

Texture create_filled_texture(int width, int height, const TexelFormat& format, const void* data) {
  Texture t = create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), 1, format.internal_format, width, height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, format.unpack_alignment);
  glTextureSubImage2D(t.id(), 0, 0, 0, width, height, format.format, format.type, data);
  return t;
}

namespace {
template <class T>
std::vector<T> read_texels(GLuint texture, int width, int height, const TexelFormat& format) {
  std::vector<T> out(static_cast<std::size_t>(width) * height * format.bytes_per_texel / sizeof(T));
  glPixelStorei(GL_PACK_ALIGNMENT, format.unpack_alignment);
  glGetTextureImage(texture, 0, format.format, format.type, static_cast<GLsizei>(out.size() * sizeof(T)), out.data());
  return out;
}
}  // namespace

std::vector<float> read_height_texels(GLuint texture, int width, int height) {
  return read_texels<float>(texture, width, height, kHeightTexels);
}

std::vector<std::uint8_t> read_imagery_texels(GLuint texture, int width, int height) {
  return read_texels<std::uint8_t>(texture, width, height, kImageryTexels);
}

}  // namespace ig::gl
