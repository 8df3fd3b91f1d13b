#include "gl/uniform.h"

namespace ig::gl {

void Uniform::set(int v) const { glProgramUniform1i(program_, location_, v); }
void Uniform::set(float v) const { glProgramUniform1f(program_, location_, v); }
void Uniform::set(const glm::ivec2& v) const { glProgramUniform2i(program_, location_, v.x, v.y); }
void Uniform::set(const glm::vec3& v) const { glProgramUniform3f(program_, location_, v.x, v.y, v.z); }
void Uniform::set(const float* values, int count) const { glProgramUniform1fv(program_, location_, count, values); }

}  // namespace ig::gl
