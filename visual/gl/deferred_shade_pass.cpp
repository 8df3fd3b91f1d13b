#include "gl/deferred_shade_pass.h"

#include "gl/frame_state.h"
#include "gl/fullscreen_triangle.h"
#include "gl/scoped_disable.h"
#include "gl/texture_units.h"

namespace ig::gl {

void DeferredShadePass::run(const RenderTarget& target, const ShaderProgram& program, PassRecorder& recorder,
                            bool water_marks) const {
  // The surface targets are read, not written.
  if (water_marks) {
    target.bind_color_and_water_marks();
  } else {
    target.bind_color_only();
  }
  program.use();
  glBindTextureUnit(unit(TextureUnit::kSurface), target.surface_texture());
  glBindTextureUnit(unit(TextureUnit::kFootprint), target.footprint_texture());
  program.set("u_surface", unit(TextureUnit::kSurface));
  program.set("u_footprint", unit(TextureUnit::kFootprint));
  // The triangle lies at the far plane (depth 0 in reversed-Z): it passes
  // where terrain is nearer, and the sky's pixels (still 0) are skipped.
  const ScopedDisable no_culling(GL_CULL_FACE);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  draw_fullscreen_triangle(empty_vao_, recorder, "shade");
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  use_frame_depth_test();
  if (water_marks) target.bind_color_only();
}

}  // namespace ig::gl
