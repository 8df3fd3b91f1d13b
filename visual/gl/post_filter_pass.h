#pragma once
// The anti-aliasing post filter: a full-screen pass reading the drawn frame
// of a post-filtered target and writing its output (shaders/edge_aa.frag).
// The program is made on first use, so a scene without a post-filtered
// target never compiles it.

#include <string>

#include "gl/gl_objects.h"
#include "gl/render_target.h"
#include "gl/shader_program.h"
#include "gl/work_counters.h"

namespace ig::gl {

class PostFilterPass {
 public:
  explicit PostFilterPass(std::string shader_dir) : shader_dir_(std::move(shader_dir)) {}
  // Filters `target`'s drawn colour into its output, recorded as pass "aa".
  void run(const RenderTarget& target, PassRecorder& recorder);

 private:
  std::string shader_dir_;
  ShaderProgram program_;
  VertexArray empty_vao_;  // the full-screen triangle needs no vertices
};

}  // namespace ig::gl
