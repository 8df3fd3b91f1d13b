// Windowed context through GLFW (needs an X display; xvfb-run in CI).
#include <epoxy/gl.h>
#include <GLFW/glfw3.h>  // GLFW_INCLUDE_NONE comes from visual/CMakeLists.txt

#include "gl/gl_context.h"

namespace ig::gl {
namespace {

class GlfwContext final : public GlContext {
 public:
  explicit GlfwContext(const ContextOptions& o) {
    if (!glfwInit()) throw GlError("GLFW: glfwInit failed (no X display? use --headless)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWmonitor* monitor = o.fullscreen ? glfwGetPrimaryMonitor() : nullptr;
    int w = o.width, h = o.height;
    if (monitor) {
      const GLFWvidmode* mode = glfwGetVideoMode(monitor);
      w = mode->width;
      h = mode->height;
    }
    window_ = glfwCreateWindow(w, h, o.title.c_str(), monitor, nullptr);
    if (!window_) {
      glfwTerminate();
      throw GlError("GLFW: could not create a window with an OpenGL 4.5 core context");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(o.vsync ? 1 : 0);
    read_strings();
  }

  ~GlfwContext() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }

  bool headless() const override { return false; }
  bool should_close() override {
    glfwPollEvents();
    return glfwWindowShouldClose(window_);
  }

  void present(unsigned fbo, int width, int height) override {
    int ww = 0, wh = 0;
    glfwGetFramebufferSize(window_, &ww, &wh);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, width, height, 0, 0, ww, wh, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glfwSwapBuffers(window_);
  }
  void make_current() override {
    if (glfwGetCurrentContext() != window_) glfwMakeContextCurrent(window_);
  }

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace

std::unique_ptr<GlContext> create_window_context(const ContextOptions& options) {
  return std::make_unique<GlfwContext>(options);
}

}  // namespace ig::gl
