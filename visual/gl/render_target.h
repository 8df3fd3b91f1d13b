#pragma once
// An offscreen framebuffer: colour (RGBA8 unless asked otherwise) + 32-bit
// float depth (reversed-Z needs the float depth buffer for its precision).
// Every frame, headless or windowed, is drawn here first.
//
// Anti-aliased frames draw elsewhere first and leave the picture here:
// - multisampled (samples > 1): passes draw into multisampled colour and
//   depth; resolve() averages the colour samples into the single-sampled
//   colour texture and copies one depth sample per pixel;
// - post-filtered (post_pass): passes draw into a colour texture of their
//   own (depth is shared); the caller's full-screen pass reads it
//   (drawn_color_texture) and writes the picture (bind_output).
// Everything that reads the frame afterwards (capture, present, image error)
// reads the picture: fbo(), color_texture(), depth_texture().
//
// Deferred shading (single-sampled only) adds two surface targets the
// terrain passes write beside the colour (attachments 1 and 2: each pixel's
// surface coordinate and distance, RGBA32F, and the coordinate's screen
// derivatives, RGBA32F: the shading's inputs exactly, so the picture is
// the same as shading in the terrain passes; shaders/shade_deferred.frag),
// made on first use.

#include <epoxy/gl.h>

#include <cstdint>
#include <vector>

#include "gl/gl_objects.h"

namespace ig::gl {

class RenderTarget {
 public:
  // color_format: GL_RGBA8 for frames; e.g. GL_RGBA16F for data targets.
  // samples: 1 = no multisampling; more is clamped to GL_MAX_SAMPLES.
  // post_pass (single-sampled only): a separate texture to draw into.
  RenderTarget(int width, int height, GLenum color_format = GL_RGBA8, int samples = 1, bool post_pass = false);
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  // The framebuffer passes draw into (the multisampled one when multisampled).
  void bind() const;
  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  bool post_pass() const { return bool(draw_fbo_) && samples_ == 1; }
  // Multisampled: the drawn samples averaged into the single-sampled colour
  // texture (depth: one sample per pixel). Nothing to do otherwise.
  void resolve() const;
  // Post-filtered: binds the picture's framebuffer (colour only) for the pass
  // that writes it.
  void bind_output() const;
  // The same with a depth buffer of the output's own (made on first use; the
  // frame's depth is left as drawn), which the pass may fill with a mask of
  // the pixels to work on and test against.
  void bind_output_with_mask() const;
  // Deferred shading in a scene with water: a single-channel target the
  // shading pass marks water in beside the colour (made on first use, each
  // call clears it for a new frame), and that pass's binding with it.
  void use_water_marks() const;
  void bind_color_and_water_marks() const;
  GLuint water_marks_texture() const { return water_marks_.id(); }
  // The water pass: the colour the passes drew with a depth buffer of the
  // pass's own (made on first use; the frame's depth is left as drawn) for
  // its mask of the pixels that may hold water.
  void bind_with_water_mask() const;
  // The picture: the single-sampled framebuffer and its textures.
  GLuint fbo() const { return fbo_.id(); }
  GLuint color_texture() const { return color_.id(); }
  GLuint depth_texture() const { return depth_.id(); }
  // What the passes drew: a GL_TEXTURE_2D_MULTISAMPLE when multisampled,
  // their own texture when post-filtered, else color_texture().
  GLuint drawn_color_texture() const { return draw_color_ ? draw_color_.id() : color_.id(); }

  // Deferred shading: makes the surface targets (once; throws GlError when
  // multisampled) and from now on bind() draws into them too.
  void use_surface_targets() const;
  GLuint surface_texture() const { return surface_.id(); }
  GLuint footprint_texture() const { return footprint_.id(); }
  // Binds the framebuffer the passes draw into with the colour alone as
  // output, for the pass that reads the surface targets.
  void bind_color_only() const;

  // The colour the passes drew (multisampled: the resolved picture) with no
  // depth attached, so a pass can read depth_texture() while it blends over
  // the frame (the clouds). Made on first use.
  void bind_color_without_depth() const;

  // Read back (after resolve()), top row first (image order). RGBA8 and float depth.
  std::vector<std::uint8_t> read_rgba() const;
  std::vector<float> read_depth() const;

 private:
  // The framebuffer the passes draw into.
  GLuint drawing_fbo() const { return draw_fbo_ ? draw_fbo_.id() : fbo_.id(); }

  int width_, height_;
  int samples_ = 1;
  Framebuffer fbo_;
  Texture color_, depth_;
  Framebuffer draw_fbo_;  // multisampled or post-filtered only
  Texture draw_color_, draw_depth_;  // draw_depth_: multisampled only (post-filtered shares depth_)
  // Made on first use by a frame that asks for them (use_surface_targets).
  mutable Texture surface_, footprint_;
  mutable Framebuffer masked_output_fbo_;
  mutable Texture output_mask_;
  mutable Texture water_marks_;
  mutable Framebuffer water_fbo_;
  mutable Framebuffer no_depth_fbo_;
  mutable Texture water_mask_;
};

// The largest sample count the context offers (GL_MAX_SAMPLES).
int max_samples();

}  // namespace ig::gl
