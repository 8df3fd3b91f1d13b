#include "gl/gl_context.h"

#include <epoxy/gl.h>

#include <cstdlib>

#include "gl/draw_pacing.h"

namespace ig::gl {

void GlContext::read_strings() {
  auto str = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "unknown");
  };
  version_ = str(GL_VERSION);
  renderer_ = str(GL_RENDERER);
  set_draw_pacing(needs_draw_pacing(renderer_));
}

std::unique_ptr<GlContext> create_context(const ContextOptions& options) {
  const char* display = std::getenv("DISPLAY");
  const bool have_display = display && *display;
  if (options.headless || !have_display) return create_headless_context();
  return create_window_context(options);
}

}  // namespace ig::gl
