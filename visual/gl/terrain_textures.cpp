#include "gl/terrain_textures.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace ig::gl {

int max_texture_size() {
  GLint size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
  return int(size);
}

Texture upload_height_texture(int width, int height, const float* heights) {
  Texture t = create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), 1, GL_R32F, width, height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(t.id(), 0, 0, 0, width, height, GL_RED, GL_FLOAT, heights);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

Texture upload_height_differences_texture(int width, int height, const float* heights) {
  Texture t = create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), 1, GL_RG16F, width, height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  // A row at a time: no copy of the whole DEM.
  std::vector<float> row(2 * std::size_t(width));
  for (int j = 0; j < height; ++j) {
    const float* up = heights + std::size_t(std::min(j + 1, height - 1)) * width;
    const float* down = heights + std::size_t(std::max(j - 1, 0)) * width;
    const float* here = heights + std::size_t(j) * width;
    for (int i = 0; i < width; ++i) {
      row[2 * i] = here[std::min(i + 1, width - 1)] - here[std::max(i - 1, 0)];
      row[2 * i + 1] = up[i] - down[i];
    }
    glTextureSubImage2D(t.id(), 0, 0, j, width, 1, GL_RG, GL_FLOAT, row.data());
  }
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

Texture upload_colour_texture(int width, int height, const unsigned char* pixels, bool rgba, bool repeat) {
  Texture t = create_texture(GL_TEXTURE_2D);
  const int levels = 1 + int(std::floor(std::log2(std::max(width, height))));
  glTextureStorage2D(t.id(), levels, rgba ? GL_RGBA8 : GL_RGB8, width, height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(t.id(), 0, 0, 0, width, height, rgba ? GL_RGBA : GL_RGB, GL_UNSIGNED_BYTE, pixels);
  glGenerateTextureMipmap(t.id());
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  const GLint wrap = repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, wrap);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, wrap);
  return t;
}

void bind_texture(TextureUnit u, const Texture& texture) { glBindTextureUnit(GLuint(unit(u)), texture.id()); }
void bind_texture(TextureUnit u, GLuint texture) { glBindTextureUnit(GLuint(unit(u)), texture); }


}  // namespace ig::gl
