#pragma once
// The sky: one full-screen triangle drawn after the terrain, only where the
// depth buffer still holds the clear value (shaders/sky.vert, sky.frag,
// sky_colour.frag).

#include <string>

#include <glm/mat4x4.hpp>

#include "environment/sky_light.h"
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "gl/work_counters.h"

namespace ig::gl {

// The uniforms of shaders/sky_colour.frag: the sky a program draws or
// mirrors (the sky pass, water).
void set_sky_colours(const ShaderProgram& program, const environment::SkyLight& sky);

class SkyPass {
 public:
  explicit SkyPass(const std::string& shader_dir);
  // Draws the sky for a view (its inverse view-projection) into the bound
  // target, recorded as pass "sky"; leaves the depth test as the frame's.
  void draw(const glm::mat4& inv_view_proj, const environment::SkyLight& sky, PassRecorder& recorder) const;

 private:
  ShaderProgram program_;
  VertexArray empty_vao_;  // the full-screen triangle needs no vertices
};

}  // namespace ig::gl
