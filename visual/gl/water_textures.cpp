#include "gl/water_textures.h"

#include <algorithm>
#include <cmath>

namespace ig::gl {
namespace {

int mip_levels(int width, int height) { return 1 + int(std::floor(std::log2(std::max(width, height)))); }

}  // namespace

Texture upload_water_share_texture(int width, int height, const ShareRows& rows) {
  Texture t = create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), mip_levels(width, height), GL_R8, width, height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  rows([&](int j, const std::uint8_t* share) {
    glTextureSubImage2D(t.id(), 0, 0, j, width, 1, GL_RED, GL_UNSIGNED_BYTE, share);
  });
  glGenerateTextureMipmap(t.id());
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

Texture upload_wave_texture(int size, const float* rgba) {
  Texture t = create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), mip_levels(size, size), GL_RGBA16F, size, size);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(t.id(), 0, 0, 0, size, size, GL_RGBA, GL_FLOAT, rgba);
  glGenerateTextureMipmap(t.id());
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  return t;
}

Texture upload_water_presence_texture(const std::vector<PresenceTexels>& levels) {
  Texture t = create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), GLsizei(levels.size()), GL_R8, levels.front().width, levels.front().height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (std::size_t k = 0; k < levels.size(); ++k)
    glTextureSubImage2D(t.id(), GLint(k), 0, 0, levels[k].width, levels[k].height, GL_RED, GL_UNSIGNED_BYTE,
                        levels[k].texels);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_MAX_LEVEL, GLint(levels.size()) - 1);
  return t;
}

}  // namespace ig::gl
