#include "gl/render_target.h"

#include <algorithm>
#include <string>

#include "gl/gl_context.h"

namespace ig::gl {
namespace {
void check_complete(GLuint fbo, int width, int height, int samples) {
  const GLenum status = glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw GlError("framebuffer " + std::to_string(width) + "x" + std::to_string(height) +
                  (samples > 1 ? " (" + std::to_string(samples) + " samples)" : std::string()) +
                  " incomplete (status 0x" + std::to_string(status) + ")");
}
}  // namespace

int max_samples() {
  GLint n = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &n);
  return std::max(1, int(n));
}

RenderTarget::RenderTarget(int width, int height, GLenum color_format, int samples, bool post_pass)
    : width_(width),
      height_(height),
      samples_(std::clamp(samples, 1, max_samples())),
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
  check_complete(fbo_.id(), width, height, 1);
  if (samples_ > 1) {
    draw_fbo_ = create_framebuffer();
    draw_color_ = create_texture(GL_TEXTURE_2D_MULTISAMPLE);
    draw_depth_ = create_texture(GL_TEXTURE_2D_MULTISAMPLE);
    // Fixed sample locations: the same pattern in every pixel, so a resolved
    // edge does not depend on where it falls.
    glTextureStorage2DMultisample(draw_color_.id(), samples_, color_format, width, height, GL_TRUE);
    glTextureStorage2DMultisample(draw_depth_.id(), samples_, GL_DEPTH_COMPONENT32F, width, height, GL_TRUE);
    glNamedFramebufferTexture(draw_fbo_.id(), GL_COLOR_ATTACHMENT0, draw_color_.id(), 0);
    glNamedFramebufferTexture(draw_fbo_.id(), GL_DEPTH_ATTACHMENT, draw_depth_.id(), 0);
    check_complete(draw_fbo_.id(), width, height, samples_);
  } else if (post_pass) {
    // The post pass reads the drawn colour with bilinear taps between pixels.
    draw_fbo_ = create_framebuffer();
    draw_color_ = create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(draw_color_.id(), 1, color_format, width, height);
    glTextureParameteri(draw_color_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(draw_color_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(draw_color_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(draw_color_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glNamedFramebufferTexture(draw_fbo_.id(), GL_COLOR_ATTACHMENT0, draw_color_.id(), 0);
    glNamedFramebufferTexture(draw_fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    check_complete(draw_fbo_.id(), width, height, 1);
  }
}

void RenderTarget::bind() const {
  const GLuint fbo = drawing_fbo();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  if (surface_) {
    const GLenum all[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glNamedFramebufferDrawBuffers(fbo, 3, all);
  }
  glViewport(0, 0, width_, height_);
}

void RenderTarget::bind_color_only() const {
  const GLuint fbo = drawing_fbo();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glNamedFramebufferDrawBuffer(fbo, GL_COLOR_ATTACHMENT0);
  glViewport(0, 0, width_, height_);
}

void RenderTarget::use_surface_targets() const {
  if (surface_) return;
  if (samples_ > 1) throw GlError("deferred shading needs a single-sampled frame (render.deferred_shading with msaa)");
  const GLuint fbo = drawing_fbo();
  surface_ = create_texture(GL_TEXTURE_2D);
  footprint_ = create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(surface_.id(), 1, GL_RGBA32F, width_, height_);
  glTextureStorage2D(footprint_.id(), 1, GL_RGBA32F, width_, height_);
  for (GLuint t : {surface_.id(), footprint_.id()}) {
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, surface_.id(), 0);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT2, footprint_.id(), 0);
  check_complete(fbo, width_, height_, 1);
}

void RenderTarget::bind_output() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width_, height_);
}

void RenderTarget::bind_output_with_mask() const {
  if (!masked_output_fbo_) {
    masked_output_fbo_ = create_framebuffer();
    output_mask_ = create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(output_mask_.id(), 1, GL_DEPTH_COMPONENT16, width_, height_);
    glNamedFramebufferTexture(masked_output_fbo_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
    glNamedFramebufferTexture(masked_output_fbo_.id(), GL_DEPTH_ATTACHMENT, output_mask_.id(), 0);
    check_complete(masked_output_fbo_.id(), width_, height_, 1);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, masked_output_fbo_.id());
  glViewport(0, 0, width_, height_);
}

void RenderTarget::bind_color_without_depth() const {
  if (!no_depth_fbo_) {
    no_depth_fbo_ = create_framebuffer();
    const GLuint colour = post_pass() ? draw_color_.id() : color_.id();
    glNamedFramebufferTexture(no_depth_fbo_.id(), GL_COLOR_ATTACHMENT0, colour, 0);
    check_complete(no_depth_fbo_.id(), width_, height_, 1);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, no_depth_fbo_.id());
  glViewport(0, 0, width_, height_);
}

void RenderTarget::use_water_marks() const {
  if (!water_marks_) {
    if (samples_ > 1) throw GlError("water marks need a single-sampled frame");
    water_marks_ = create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(water_marks_.id(), 1, GL_R8, width_, height_);
    glTextureParameteri(water_marks_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(water_marks_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glNamedFramebufferTexture(drawing_fbo(), GL_COLOR_ATTACHMENT3, water_marks_.id(), 0);
    check_complete(drawing_fbo(), width_, height_, 1);
  }
  // Pixels the shading pass leaves (sky) must not keep last frame's marks.
  const GLubyte zero = 0;
  glClearTexImage(water_marks_.id(), 0, GL_RED, GL_UNSIGNED_BYTE, &zero);
}

void RenderTarget::bind_color_and_water_marks() const {
  const GLuint fbo = drawing_fbo();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  const GLenum outputs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT3};
  glNamedFramebufferDrawBuffers(fbo, 2, outputs);
  glViewport(0, 0, width_, height_);
}

void RenderTarget::bind_with_water_mask() const {
  if (!water_fbo_) {
    water_fbo_ = create_framebuffer();
    water_mask_ = create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(water_mask_.id(), 1, GL_DEPTH_COMPONENT16, width_, height_);
    glNamedFramebufferTexture(water_fbo_.id(), GL_COLOR_ATTACHMENT0, drawn_color_texture(), 0);
    glNamedFramebufferTexture(water_fbo_.id(), GL_DEPTH_ATTACHMENT, water_mask_.id(), 0);
    check_complete(water_fbo_.id(), width_, height_, 1);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, water_fbo_.id());
  glViewport(0, 0, width_, height_);
}

void RenderTarget::resolve() const {
  if (samples_ <= 1) return;
  // Colour: the samples' mean (a box filter over the pixel); depth cannot be
  // averaged, GL_NEAREST takes one sample.
  glBlitNamedFramebuffer(draw_fbo_.id(), fbo_.id(), 0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                         GL_LINEAR);
  glBlitNamedFramebuffer(draw_fbo_.id(), fbo_.id(), 0, 0, width_, height_, 0, 0, width_, height_, GL_DEPTH_BUFFER_BIT,
                         GL_NEAREST);
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
