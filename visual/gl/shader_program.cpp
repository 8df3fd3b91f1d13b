#include "gl/shader_program.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "gl/gl_context.h"

namespace ig::gl {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw GlError("shader " + path + ": cannot be read");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A shader's or program's info log (get_iv / get_log: the glGet*iv and
// glGet*InfoLog pair of its kind).
template <class GetIv, class GetLog>
std::string info_log(GLuint object, GetIv get_iv, GetLog get_log) {
  GLint len = 0;
  get_iv(object, GL_INFO_LOG_LENGTH, &len);
  std::string log(std::max(len, 1), '\0');
  get_log(object, len, nullptr, log.data());
  return log;
}

GLuint compile(GLenum stage, const std::string& path) {
  const std::string source = read_text(path);
  GLuint s = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(s, glGetShaderiv, glGetShaderInfoLog);
    glDeleteShader(s);
    throw GlError("shader " + path + ": compile failed: " + log);
  }
  return s;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::string& dir, const std::string& vertex_file,
                             const std::string& fragment_file)
    : ShaderProgram(dir, vertex_file, std::vector<std::string>{fragment_file}) {}

ShaderProgram::ShaderProgram(const std::string& dir, const std::string& vertex_file,
                             const std::vector<std::string>& fragment_files) {
  std::vector<GLuint> shaders;
  std::string names = vertex_file;
  try {
    shaders.push_back(compile(GL_VERTEX_SHADER, dir + "/" + vertex_file));
    for (const auto& f : fragment_files) {
      shaders.push_back(compile(GL_FRAGMENT_SHADER, dir + "/" + f));
      names += " + " + f;
    }
  } catch (...) {
    for (GLuint sh : shaders) glDeleteShader(sh);
    throw;
  }
  id_ = glCreateProgram();
  for (GLuint sh : shaders) glAttachShader(id_, sh);
  glLinkProgram(id_);
  for (GLuint sh : shaders) glDeleteShader(sh);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(id_, glGetProgramiv, glGetProgramInfoLog);
    glDeleteProgram(id_);
    id_ = 0;
    throw GlError("program " + dir + "/{" + names + "}: link failed: " + log);
  }
}

ShaderProgram::~ShaderProgram() {
  if (id_) glDeleteProgram(id_);
}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& o) noexcept {
  if (this != &o) {
    if (id_) glDeleteProgram(id_);
    id_ = o.id_;
    o.id_ = 0;
    locations_ = std::move(o.locations_);
  }
  return *this;
}

GLint ShaderProgram::location(const char* name) const {
  const std::string_view key(name);
  if (auto it = locations_.find(key); it != locations_.end()) return it->second;
  const GLint loc = glGetUniformLocation(id_, name);
  locations_.emplace(std::string(key), loc);
  return loc;
}

void ShaderProgram::set(const char* n, const glm::vec2& v) const { glProgramUniform2fv(id_, location(n), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* n, const glm::vec3& v) const { glProgramUniform3fv(id_, location(n), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* n, const glm::vec4& v) const { glProgramUniform4fv(id_, location(n), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* n, const glm::ivec2& v) const { glProgramUniform2iv(id_, location(n), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* n, const glm::mat4& m) const {
  glProgramUniformMatrix4fv(id_, location(n), 1, GL_FALSE, glm::value_ptr(m));
}

std::string installed_data_dir(const std::string& name, const std::string& probe) {
  std::vector<char> buf(4096);
  const ssize_t n = readlink("/proc/self/exe", buf.data(), buf.size() - 1);
  if (n <= 0) return "";
  const std::filesystem::path bin = std::filesystem::path(std::string(buf.data(), size_t(n))).parent_path();
  // Build tree: beside the binary; installed: PREFIX/share/ig beside PREFIX/bin.
  for (const auto& dir : {bin / name, bin.parent_path() / "share" / "ig" / name})
    if (std::filesystem::exists(dir / probe)) return dir.string();
  return "";
}

std::string default_shader_dir() {
  if (const char* env = std::getenv("IG_SHADER_DIR"); env && *env) return env;
  if (auto dir = installed_data_dir("shaders", "sky.vert"); !dir.empty()) return dir;
  return "shaders";  // relative to the working directory: no build path is compiled in
}

}  // namespace ig::gl
