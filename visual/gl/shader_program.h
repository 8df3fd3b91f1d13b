#pragma once
// GLSL programs loaded at run time from the shader directory (one file per
// stage). Compile and link errors name the file and carry the driver's log.

#include <epoxy/gl.h>

#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace ig::gl {

class ShaderProgram {
 public:
  ShaderProgram() = default;
  // Loads <dir>/<vertex_file> and <dir>/<fragment_file>. Throws GlError.
  ShaderProgram(const std::string& dir, const std::string& vertex_file,
                const std::string& fragment_file);
  // Several fragment shader objects linked into one stage (one holds main,
  // the others shared functions such as terrain_shading.frag).
  ShaderProgram(const std::string& dir, const std::string& vertex_file,
                const std::vector<std::string>& fragment_files);
  ~ShaderProgram();
  ShaderProgram(ShaderProgram&& o) noexcept : id_(o.id_), locations_(std::move(o.locations_)) { o.id_ = 0; }
  ShaderProgram& operator=(ShaderProgram&& o) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  GLuint id() const { return id_; }
  void use() const { glUseProgram(id_); }
  // Cached per program: uniforms are set per block per frame, and the
  // driver's lookup is a string search (-1 for names the program lacks).
  GLint location(const char* name) const;
  void set(const char* name, int v) const { glProgramUniform1i(id_, location(name), v); }
  void set(const char* name, float v) const { glProgramUniform1f(id_, location(name), v); }
  void set(const char* name, const glm::vec2& v) const;
  void set(const char* name, const glm::vec3& v) const;
  void set(const char* name, const glm::vec4& v) const;
  void set(const char* name, const glm::ivec2& v) const;
  void set(const char* name, const glm::mat4& m) const;

 private:
  struct NameHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
  };
  GLuint id_ = 0;
  mutable std::unordered_map<std::string, GLint, NameHash, std::equal_to<>> locations_;
};

// Directory holding the GLSL files: $IG_SHADER_DIR, else "shaders" beside
// the executable (build tree), else PREFIX/share/ig/shaders for an installed
// PREFIX/bin/ig (cmake --install), else "shaders" in the working directory.
std::string default_shader_dir();
// A data folder of an installed or built ig: NAME beside the executable or
// in ../share/ig/NAME, whichever holds the file `probe`; "" when neither.
std::string installed_data_dir(const std::string& name, const std::string& probe);

}  // namespace ig::gl
