#pragma once
// OpenGL 4.5 core context, headless (EGL, Mesa surfaceless platform) or in a
// window (GLFW). The renderer never sees which: it always draws into its own
// framebuffer object; a window merely shows that image (present()).

#include <memory>
#include <stdexcept>
#include <string>

namespace ig::gl {

struct GlError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ContextOptions {
  bool headless = true;
  int width = 640;   // window size (ignored headless)
  int height = 480;
  bool fullscreen = false;
  bool vsync = true;
  std::string title = "ig";
};

class GlContext {
 public:
  virtual ~GlContext() = default;
  virtual bool headless() const = 0;
  // Window closed by the user (always false headless).
  virtual bool should_close() = 0;
  // Show the given framebuffer object's colour attachment 0 and swap buffers
  // (no-op headless).
  virtual void present(unsigned fbo, int width, int height) = 0;
  // Makes this context the thread's current one (a context is current from
  // its creation; with several on one thread, whoever draws makes its own
  // current first). Cheap when it already is.
  virtual void make_current() = 0;
  const std::string& gl_version() const { return version_; }
  const std::string& gl_renderer() const { return renderer_; }

 protected:
  // Fills version_/renderer_ once the context is current, and paces draws
  // on a software rasterizer (gl/draw_pacing.h).
  void read_strings();
  std::string version_, renderer_;
};

// Throws GlError with a one-line reason when no 4.5 core context can be made.
std::unique_ptr<GlContext> create_headless_context();
std::unique_ptr<GlContext> create_window_context(const ContextOptions& options);
// Headless when options.headless, or when there is no DISPLAY.
std::unique_ptr<GlContext> create_context(const ContextOptions& options);

}  // namespace ig::gl
