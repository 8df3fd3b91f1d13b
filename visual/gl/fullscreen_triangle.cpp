#include "gl/fullscreen_triangle.h"

#include <epoxy/gl.h>

namespace ig::gl {

void draw_fullscreen_triangle(const VertexArray& empty_vao, PassRecorder& recorder, std::string_view pass) {
  glBindVertexArray(empty_vao.id());
  recorder.begin(pass);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  count_draw();
  recorder.end();
}

}  // namespace ig::gl
