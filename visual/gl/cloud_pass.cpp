#include "gl/cloud_pass.h"

#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "environment/cloud_noise.h"
#include "gl/gl_context.h"
#include "gl/fullscreen_triangle.h"
#include "gl/scoped_disable.h"
#include "gl/texture_units.h"

namespace ig::gl {
namespace {

Texture upload_cloud_noise() {
  const int side = environment::kCloudNoiseSide;
  const auto field = environment::cloud_noise_field();
  Texture t = create_texture(GL_TEXTURE_2D);
  const int levels = 1 + int(std::log2(double(side)));
  glTextureStorage2D(t.id(), levels, GL_R16F, side, side);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(t.id(), 0, 0, 0, side, side, GL_RED, GL_FLOAT, field.data());
  glGenerateTextureMipmap(t.id());
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  count_upload(std::size_t(side) * side * 2);
  return t;
}

}  // namespace

CloudPass::CloudPass(const std::string& shader_dir)
    : march_(shader_dir, "fullscreen.vert", "clouds.frag"),
      upsample_(shader_dir, "fullscreen.vert", "clouds_upsample.frag"),
      noise_(upload_cloud_noise()),
      empty_vao_(create_vertex_array()) {}

void CloudPass::make_half_target(int width, int height) {
  frame_size_ = {width, height};
  const int w = (width + 1) / 2, h = (height + 1) / 2;
  light_ = create_texture(GL_TEXTURE_2D);
  depth_ = create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(light_.id(), 1, GL_RGBA16F, w, h);
  glTextureStorage2D(depth_.id(), 1, GL_R32F, w, h);
  half_ = create_framebuffer();
  glNamedFramebufferTexture(half_.id(), GL_COLOR_ATTACHMENT0, light_.id(), 0);
  glNamedFramebufferTexture(half_.id(), GL_COLOR_ATTACHMENT1, depth_.id(), 0);
  const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(half_.id(), 2, buffers);
  if (glCheckNamedFramebufferStatus(half_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw GlError("cloud target " + std::to_string(w) + "x" + std::to_string(h) + " incomplete");
}

void CloudPass::draw(const environment::CloudFrame& clouds, const CloudView& view, const RenderTarget& target,
                     PassRecorder& recorder) {
  if (frame_size_ != glm::ivec2(target.width(), target.height())) make_half_target(target.width(), target.height());
  ScopedDisable no_depth(GL_DEPTH_TEST), no_cull(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glBindFramebuffer(GL_FRAMEBUFFER, half_.id());
  glViewport(0, 0, (target.width() + 1) / 2, (target.height() + 1) / 2);
  march_.use();
  glBindTextureUnit(unit(TextureUnit::kFrameDepth), target.depth_texture());
  glBindTextureUnit(unit(TextureUnit::kCloudNoise), noise_.id());
  march_.set("u_depth", unit(TextureUnit::kFrameDepth));
  march_.set("u_noise", unit(TextureUnit::kCloudNoise));
  march_.set("u_inv_view_proj", view.inv_view_proj);
  march_.set("u_viewport", glm::vec2(float(target.width()), float(target.height())));
  march_.set("u_eye_alt", view.eye_altitude_m);
  march_.set("u_curve_k", view.earth_radius_m > 0.0 ? float(0.5 / view.earth_radius_m) : 0.0f);
  const double half = 0.5 * view.fov_y_deg * 3.14159265358979323846 / 180.0;
  march_.set("u_pixel_spread", float(2.0 * std::tan(half) / double(target.height())));
  march_.set("u_layers", clouds.layers);
  glProgramUniform4fv(march_.id(), march_.location("u_layer"), 4 * clouds.layers,
                      glm::value_ptr(clouds.packed[0]));
  march_.set("u_sun", clouds.sun_direction);
  march_.set("u_sun_light", clouds.sun_light);
  march_.set("u_sky_top", clouds.sky_light_top);
  march_.set("u_sky_base", clouds.sky_light_base);
  march_.set("u_shadow_floor", clouds.shadow_floor);
  march_.set("u_fog_k", view.fog_k);
  march_.set("u_fog_color", view.fog_colour);
  draw_fullscreen_triangle(empty_vao_, recorder, "clouds");

  target.bind_color_without_depth();
  upsample_.use();
  glBindTextureUnit(unit(TextureUnit::kCloudLight), light_.id());
  glBindTextureUnit(unit(TextureUnit::kCloudDepth), depth_.id());
  upsample_.set("u_depth", unit(TextureUnit::kFrameDepth));
  upsample_.set("u_cloud_light", unit(TextureUnit::kCloudLight));
  upsample_.set("u_cloud_depth", unit(TextureUnit::kCloudDepth));
  glEnable(GL_BLEND);
  // Colour: the clouds' light plus what shows through (alpha); the frame's
  // alpha (coverage codes for the anti-aliasing pass) is kept.
  glBlendFuncSeparate(GL_ONE, GL_SRC_ALPHA, GL_ZERO, GL_ONE);
  draw_fullscreen_triangle(empty_vao_, recorder, "clouds");
  glDisable(GL_BLEND);
  glBindTextureUnit(unit(TextureUnit::kFrameDepth), 0);
  target.bind();
}

}  // namespace ig::gl
