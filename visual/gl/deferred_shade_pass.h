#pragma once
// Deferred shading's full-screen pass: every pixel the terrain covers is
// shaded once from the surface targets the terrain passes wrote
// (shaders/deferred_shade.frag), only where the depth buffer holds terrain;
// the coverage code in the colour's alpha is kept.

#include "gl/gl_objects.h"
#include "gl/render_target.h"
#include "gl/shader_program.h"
#include "gl/work_counters.h"

namespace ig::gl {

class DeferredShadePass {
 public:
  DeferredShadePass() : empty_vao_(create_vertex_array()) {}
  // Into `target` (drawn with its surface targets), with `program`, whose
  // shading uniforms the caller has set; recorded as pass "shade". With
  // water_marks the program's second output goes to the target's water marks
  // (RenderTarget::use_water_marks). Leaves the target bound with its colour
  // as the only output and the frame's depth test.
  void run(const RenderTarget& target, const ShaderProgram& program, PassRecorder& recorder,
           bool water_marks = false) const;

 private:
  VertexArray empty_vao_;  // the full-screen triangle needs no vertices
};

}  // namespace ig::gl
