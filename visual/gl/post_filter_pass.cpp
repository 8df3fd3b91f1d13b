#include "gl/post_filter_pass.h"

#include <string>
#include <vector>

#include "gl/frame_state.h"
#include "gl/fullscreen_triangle.h"
#include "gl/scoped_disable.h"
#include "gl/texture_units.h"

namespace ig::gl {

void PostFilterPass::run(const RenderTarget& target, PassRecorder& recorder) {
  if (!filter_.id()) {
    filter_ = ShaderProgram(shader_dir_, "fullscreen.vert", std::vector<std::string>{"edge_aa.frag", "edge_test.frag"});
    mark_ = ShaderProgram(shader_dir_, "fullscreen.vert", std::vector<std::string>{"edge_mark.frag", "edge_test.frag"});
    empty_vao_ = create_vertex_array();
  }
  glBindTextureUnit(unit(TextureUnit::kFrameColor), target.drawn_color_texture());
  const ScopedDisable no_culling(GL_CULL_FACE);
  if (!edge_mask_) {
    target.bind_output();
    const ScopedDisable no_depth_test(GL_DEPTH_TEST);
    draw(filter_, recorder);
    return;
  }
  // Copy and mark every pixel, then filter where the mask says: the mask's
  // depth 1 passes the filter's triangle (depth 0, GL_LESS), 0 does not.
  target.bind_output_with_mask();
  glEnable(GL_DEPTH_TEST);  // depth is written only with the test on
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_ALWAYS);
  draw(mark_, recorder);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  draw(filter_, recorder);
  glDepthMask(GL_TRUE);
  use_frame_depth_test();
}

void PostFilterPass::draw(const ShaderProgram& program, PassRecorder& recorder) const {
  program.use();
  program.set("u_frame", unit(TextureUnit::kFrameColor));
  draw_fullscreen_triangle(empty_vao_, recorder, "aa");
}

}  // namespace ig::gl
