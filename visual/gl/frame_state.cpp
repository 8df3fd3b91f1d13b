#include "gl/frame_state.h"

#include <epoxy/gl.h>

#include "gl/coverage_codes.h"
#include "gl/draw_pacing.h"

namespace ig::gl {

void use_frame_depth_test() {
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_GREATER);
}

void begin_frame(bool cull_back_faces) {
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  use_frame_depth_test();
  if (cull_back_faces) {
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
  } else {
    glDisable(GL_CULL_FACE);
  }
  // Alpha is the coverage code: a pixel no terrain pass draws is sky until
  // the sky pass fills it, also for the two-level count that runs before it.
  glClearColor(0.f, 0.f, 0.f, coverage::kSky);
  glClearDepth(0.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void set_wireframe(bool on) { glPolygonMode(GL_FRONT_AND_BACK, on ? GL_LINE : GL_FILL); }

void finish() {
  glFinish();
  end_draw_pacing();
}

bool clip_depth_zero_to_one() {
  GLint clip_depth = 0;
  glGetIntegerv(GL_CLIP_DEPTH_MODE, &clip_depth);
  return clip_depth == GL_ZERO_TO_ONE;
}

bool is_float_depth(unsigned depth_texture) {
  GLint format = 0;
  glGetTextureLevelParameteriv(depth_texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  return format == GL_DEPTH_COMPONENT32F;
}

bool no_gl_error() { return glGetError() == GL_NO_ERROR; }

}  // namespace ig::gl
