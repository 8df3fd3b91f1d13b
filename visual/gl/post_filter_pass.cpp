#include "gl/post_filter_pass.h"

#include "gl/fullscreen_triangle.h"
#include "gl/texture_units.h"

namespace ig::gl {

void PostFilterPass::run(const RenderTarget& target, PassRecorder& recorder) {
  target.bind_output();
  glDisable(GL_DEPTH_TEST);
  if (!program_.id()) {
    program_ = ShaderProgram(shader_dir_, "fullscreen.vert", "edge_aa.frag");
    empty_vao_ = create_vertex_array();
  }
  program_.use();
  glBindTextureUnit(unit(TextureUnit::kFrameColor), target.drawn_color_texture());
  program_.set("u_frame", unit(TextureUnit::kFrameColor));
  draw_fullscreen_triangle(empty_vao_, recorder, "aa");
  glEnable(GL_DEPTH_TEST);
}

}  // namespace ig::gl
