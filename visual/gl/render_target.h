#pragma once
// An offscreen framebuffer: colour (RGBA8 unless asked otherwise) + 32-bit
// float depth (reversed-Z needs the float depth buffer for its precision).
// Every frame, headless or windowed, is drawn here first.

#include <epoxy/gl.h>

#include <cstdint>
#include <vector>

#include "gl/gl_objects.h"

namespace ig::gl {

class RenderTarget {
 public:
  // color_format: GL_RGBA8 for frames; e.g. GL_RGBA16F for data targets.
  RenderTarget(int width, int height, GLenum color_format = GL_RGBA8);
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  void bind() const;
  int width() const { return width_; }
  int height() const { return height_; }
  GLuint fbo() const { return fbo_.id(); }
  GLuint color_texture() const { return color_.id(); }
  GLuint depth_texture() const { return depth_.id(); }

  // Read back, top row first (image order). RGBA8 and float depth.
  std::vector<std::uint8_t> read_rgba() const;
  std::vector<float> read_depth() const;

 private:
  int width_, height_;
  Framebuffer fbo_;
  Texture color_, depth_;
};

}  // namespace ig::gl
