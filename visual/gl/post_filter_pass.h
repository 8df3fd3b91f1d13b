#pragma once
// The anti-aliasing post filter: reads the drawn frame of a post-filtered
// target and writes its output (shaders/edge_aa.frag). A first full-screen
// draw copies the frame and marks the pixels on a luma edge in a depth mask
// (shaders/edge_mark.frag); the filter's draw then runs on those alone,
// which spares a CPU rasterizer the filter's work on the others (a GPU
// skips them with a branch as well). The programs are made on first use, so
// a scene without a post-filtered target never compiles them.

#include <string>

#include "gl/gl_objects.h"
#include "gl/render_target.h"
#include "gl/shader_program.h"
#include "gl/work_counters.h"

namespace ig::gl {

class PostFilterPass {
 public:
  explicit PostFilterPass(std::string shader_dir) : shader_dir_(std::move(shader_dir)) {}
  // Filters `target`'s drawn colour into its output, recorded as pass "aa"
  // (two draws; one, on every pixel, without the mask).
  void run(const RenderTarget& target, PassRecorder& recorder);
  // For tests: the filter on every pixel in one draw, no mask.
  void set_edge_mask(bool on) { edge_mask_ = on; }

 private:
  void draw(const ShaderProgram& program, PassRecorder& recorder) const;

  std::string shader_dir_;
  bool edge_mask_ = true;
  ShaderProgram filter_, mark_;
  VertexArray empty_vao_;  // the full-screen triangle needs no vertices
};

}  // namespace ig::gl
