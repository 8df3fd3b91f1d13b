#include "gl/render_target.h"

#include <algorithm>
#include <string>

#include "gl/gl_context.h"

namespace ig::gl {

RenderTarget::RenderTarget(int width, int height, GLenum color_format)
    : width_(width),
      height_(height),
      fbo_(create_framebuffer()),
      color_(create_texture(GL_TEXTURE_2D)),
      depth_(create_texture(GL_TEXTURE_2D)) {
  glTextureStorage2D(color_.id(), 1, color_format, width, height);
  glTextureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, width, height);
  for (GLuint t : {color_.id(), depth_.id()}) {
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  const GLenum status = glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw GlError("framebuffer " + std::to_string(width) + "x" + std::to_string(height) +
                  " incomplete (status 0x" + std::to_string(status) + ")");
}

void RenderTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width_, height_);
}

namespace {
template <typename T>
void flip_rows(std::vector<T>& v, int width, int height, int channels) {
  const size_t row = size_t(width) * channels;
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(v.begin() + y * row, v.begin() + (y + 1) * row, v.begin() + (height - 1 - y) * row);
}
}  // namespace

std::vector<std::uint8_t> RenderTarget::read_rgba() const {
  std::vector<std::uint8_t> px(size_t(width_) * height_ * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(color_.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(px.size()), px.data());
  flip_rows(px, width_, height_, 4);
  return px;
}

std::vector<float> RenderTarget::read_depth() const {
  std::vector<float> d(size_t(width_) * height_);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(depth_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(d.size() * sizeof(float)), d.data());
  flip_rows(d, width_, height_, 1);
  return d;
}

}  // namespace ig::gl
