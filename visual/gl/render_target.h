#pragma once
// An offscreen framebuffer: colour (RGBA8 unless asked otherwise) + 32-bit
// float depth (reversed-Z needs the float depth buffer for its precision).
// Every frame, headless or windowed, is drawn here first.
//
// Multisampled (samples > 1): passes draw into multisampled colour and depth
// (bind()); resolve() averages the colour samples into a single-sampled
// colour texture and copies one depth sample per pixel, and everything that
// reads the frame afterwards (capture, present, image error) reads that.

#include <epoxy/gl.h>

#include <cstdint>
#include <vector>

#include "gl/gl_objects.h"

namespace ig::gl {

class RenderTarget {
 public:
  // color_format: GL_RGBA8 for frames; e.g. GL_RGBA16F for data targets.
  // samples: 1 = no multisampling; more is clamped to GL_MAX_SAMPLES.
  RenderTarget(int width, int height, GLenum color_format = GL_RGBA8, int samples = 1);
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  // The framebuffer passes draw into (the multisampled one when multisampled).
  void bind() const;
  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  // Multisampled: the drawn samples averaged into the single-sampled colour
  // texture (depth: one sample per pixel). Nothing to do otherwise.
  void resolve() const;
  // The single-sampled (resolved) framebuffer and its textures.
  GLuint fbo() const { return fbo_.id(); }
  GLuint color_texture() const { return color_.id(); }
  GLuint depth_texture() const { return depth_.id(); }
  // What the passes drew, before resolve(): a GL_TEXTURE_2D_MULTISAMPLE
  // when multisampled, else color_texture().
  GLuint drawn_color_texture() const { return samples_ > 1 ? ms_color_.id() : color_.id(); }

  // Read back (after resolve()), top row first (image order). RGBA8 and float depth.
  std::vector<std::uint8_t> read_rgba() const;
  std::vector<float> read_depth() const;

 private:
  int width_, height_;
  int samples_ = 1;
  Framebuffer fbo_;
  Texture color_, depth_;
  Framebuffer ms_fbo_;  // multisampled only
  Texture ms_color_, ms_depth_;
};

// The largest sample count the context offers (GL_MAX_SAMPLES).
int max_samples();

}  // namespace ig::gl
