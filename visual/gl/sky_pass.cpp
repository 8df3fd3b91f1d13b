#include "gl/sky_pass.h"

#include "gl/fullscreen_triangle.h"

namespace ig::gl {

void set_sky_colours(const ShaderProgram& program, const environment::SkyLight& sky) {
  program.set("u_sky_zenith", sky.sky_zenith);
  program.set("u_sky_horizon", sky.sky_horizon);
  program.set("u_sky_sun", sky.sun_direction);
  program.set("u_sky_glow", sky.horizon_glow);
}

SkyPass::SkyPass(const std::string& shader_dir)
    : program_(shader_dir, "sky.vert", std::vector<std::string>{"sky.frag", "sky_colour.frag"}),
      empty_vao_(create_vertex_array()) {}

void SkyPass::draw(const glm::mat4& inv_view_proj, const environment::SkyLight& sky, PassRecorder& recorder) const {
  program_.use();
  program_.set("u_inv_view_proj", inv_view_proj);
  set_sky_colours(program_, sky);
  program_.set("u_sun_disc", sky.sun_disc);
  glDisable(GL_CULL_FACE);
  glDepthFunc(GL_GEQUAL);  // only where the depth buffer still holds the clear value
  glDepthMask(GL_FALSE);
  draw_fullscreen_triangle(empty_vao_, recorder, "sky");
  glDepthMask(GL_TRUE);
}

}  // namespace ig::gl
