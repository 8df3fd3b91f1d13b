#pragma once
// Deferred shading's water pass: after the shading pass has shaded every
// terrain pixel as land and marked those where water may be
// (shaders/water_mark.frag), the water is blended over the marked pixels.
// Two full-screen draws, as the edge filter's: the first turns the marks
// into a depth mask of the pass's own (shaders/water_mask.frag), the second
// (shaders/water_shade.frag), depth-tested against it, shades them alone;
// a CPU rasterizer's early depth test skips every block of land. A scene
// without water has no such pass.

#include "gl/gl_objects.h"
#include "gl/render_target.h"
#include "gl/shader_program.h"
#include "gl/work_counters.h"

namespace ig::gl {

class WaterPass {
 public:
  WaterPass() : empty_vao_(create_vertex_array()) {}
  // Into `target` (drawn with its surface targets), with the two programs,
  // whose shading uniforms the caller has set; recorded as pass "water".
  // Leaves the target bound with its drawn colour as the only output and the
  // frame's depth test.
  void run(const RenderTarget& target, const ShaderProgram& mask, const ShaderProgram& shade,
           PassRecorder& recorder) const;

 private:
  VertexArray empty_vao_;  // the full-screen triangle needs no vertices
};

}  // namespace ig::gl
