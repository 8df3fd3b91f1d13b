#include "gl/post_filter_pass.h"

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
  glBindVertexArray(empty_vao_.id());
  glBindTextureUnit(unit(TextureUnit::kFrameColor), target.drawn_color_texture());
  program_.set("u_frame", unit(TextureUnit::kFrameColor));
  recorder.begin("aa");
  glDrawArrays(GL_TRIANGLES, 0, 3);
  count_draw();
  recorder.end();
  glEnable(GL_DEPTH_TEST);
}

}  // namespace ig::gl
