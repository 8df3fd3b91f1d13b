#include "gl/cloud_pass.h"

#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "environment/cloud_noise.h"
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
    : program_(shader_dir, "fullscreen.vert", "clouds.frag"),
      noise_(upload_cloud_noise()),
      empty_vao_(create_vertex_array()) {}

void CloudPass::draw(const environment::CloudFrame& clouds, const CloudView& view, const RenderTarget& target,
                     PassRecorder& recorder) const {
  target.bind_color_without_depth();
  program_.use();
  glBindTextureUnit(unit(TextureUnit::kFrameDepth), target.depth_texture());
  glBindTextureUnit(unit(TextureUnit::kCloudNoise), noise_.id());
  program_.set("u_depth", unit(TextureUnit::kFrameDepth));
  program_.set("u_noise", unit(TextureUnit::kCloudNoise));
  program_.set("u_inv_view_proj", view.inv_view_proj);
  program_.set("u_viewport", glm::vec2(float(target.width()), float(target.height())));
  program_.set("u_eye_alt", view.eye_altitude_m);
  program_.set("u_curve_k", view.earth_radius_m > 0.0 ? float(0.5 / view.earth_radius_m) : 0.0f);
  const double half = 0.5 * view.fov_y_deg * 3.14159265358979323846 / 180.0;
  program_.set("u_pixel_spread", float(2.0 * std::tan(half) / double(target.height())));
  program_.set("u_layers", clouds.layers);
  glProgramUniform4fv(program_.id(), program_.location("u_layer"), 4 * clouds.layers,
                      glm::value_ptr(clouds.packed[0]));
  program_.set("u_sun", clouds.sun_direction);
  program_.set("u_sun_light", clouds.sun_light);
  program_.set("u_sky_top", clouds.sky_light_top);
  program_.set("u_sky_base", clouds.sky_light_base);
  program_.set("u_shadow_floor", clouds.shadow_floor);
  program_.set("u_fog_k", view.fog_k);
  program_.set("u_fog_color", view.fog_colour);
  ScopedDisable no_depth(GL_DEPTH_TEST), no_cull(GL_CULL_FACE);
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
