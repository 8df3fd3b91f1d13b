#pragma once
// The GL side of a wrap-around window texture (render/window_texture.h): a
// 2D texture with one level, linear filtering and GL_REPEAT addressing, so
// filtering is right across the seam where the window wraps; rectangles are
// uploaded straight from the caller's rows (GL_UNPACK_ROW_LENGTH), no copy.

#include <cstdint>
#include <string>
#include <vector>

#include "gl/gl_objects.h"

namespace ig::gl {

// How one texel is stored and uploaded.
struct TexelFormat {
  GLenum internal_format, format, type;
  int bytes_per_texel, unpack_alignment;
};
inline constexpr TexelFormat kHeightTexels{GL_R32F, GL_RED, GL_FLOAT, 4, 4};         // one float height
inline constexpr TexelFormat kImageryTexels{GL_RGB8, GL_RGB, GL_UNSIGNED_BYTE, 3, 1};  // RGB8 imagery

class WindowStorage {
 public:
  // width x height texels. Throws GlError "<what> WxH exceeds the GL texture
  // limit N" if it does not fit.
  WindowStorage(int width, int height, const TexelFormat& format, const std::string& what);

  // Uploads the w x h rectangle at texel (x, y) from `data`, whose rows are
  // `row_length` texels long.
  void upload(int x, int y, int w, int h, const void* data, int row_length) const;

  GLuint id() const { return tex_.id(); }
  const TexelFormat& format() const { return format_; }

 private:
  TexelFormat format_;
  Texture tex_;
};

// A texture of `format` filled from `data` (tightly packed rows), as the
// scene makes one for a grid that fits; and reading a texture back, for tests.
Texture create_filled_texture(int width, int height, const TexelFormat& format, const void* data);
std::vector<float> read_height_texels(GLuint texture, int width, int height);
std::vector<std::uint8_t> read_imagery_texels(GLuint texture, int width, int height);

}  // namespace ig::gl
