#include "gl/water_pass.h"

#include "gl/frame_state.h"
#include "gl/fullscreen_triangle.h"
#include "gl/scoped_disable.h"
#include "gl/texture_units.h"

namespace ig::gl {
namespace {

void use_with_surface(const ShaderProgram& program) {
  program.use();
  program.set("u_surface", unit(TextureUnit::kSurface));
  program.set("u_footprint", unit(TextureUnit::kFootprint));
}

}  // namespace

void WaterPass::run(const RenderTarget& target, const ShaderProgram& mask, const ShaderProgram& shade,
                    PassRecorder& recorder) const {
  target.bind_with_water_mask();
  glBindTextureUnit(unit(TextureUnit::kSurface), target.surface_texture());
  glBindTextureUnit(unit(TextureUnit::kFootprint), target.footprint_texture());
  glBindTextureUnit(unit(TextureUnit::kWaterMarks), target.water_marks_texture());
  const ScopedDisable no_culling(GL_CULL_FACE);
  // Every pixel's mask depth from the marks, colour untouched.
  mask.use();
  mask.set("u_water_mark", unit(TextureUnit::kWaterMarks));
  glEnable(GL_DEPTH_TEST);  // depth is written only with the test on
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_ALWAYS);
  glColorMaski(0, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  draw_fullscreen_triangle(empty_vao_, recorder, "water");
  // Shade where marked: the mask's 1 passes the triangle (depth 0, GL_LESS),
  // 0 does not; the water's share of the pixel blended over the land.
  use_with_surface(shade);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  draw_fullscreen_triangle(empty_vao_, recorder, "water");
  glDisable(GL_BLEND);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  use_frame_depth_test();
  target.bind_color_only();
}

}  // namespace ig::gl
