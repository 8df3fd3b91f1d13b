#pragma once
// One uniform of one program, its location looked up once: the LOD methods
// set a few uniforms per drawn piece, thousands of times a frame, where a
// lookup by name each time would cost a string hash.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "gl/shader_program.h"

namespace ig::gl {

class Uniform {
 public:
  Uniform(const ShaderProgram& program, const char* name) : program_(program.id()), location_(program.location(name)) {}

  void set(int v) const;
  void set(float v) const;
  void set(const glm::ivec2& v) const;
  void set(const glm::vec3& v) const;
  // A float array uniform, `count` values from `values`.
  void set(const float* values, int count) const;

 private:
  GLuint program_;
  GLint location_;
};

}  // namespace ig::gl
