// Headless context: EGL on Mesa's surfaceless platform (no X, no GPU needed),
// falling back to the EGL device platform. Rendering goes to FBOs only.
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <atomic>
#include <cstdio>

#include "gl/gl_context.h"

namespace ig::gl {
namespace {

class EglContext final : public GlContext {
 public:
  EglContext() {
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_base"))
      throw GlError("EGL: EGL_EXT_platform_base is missing (is libegl-mesa0 installed?)");
    display_ = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) {
      // A machine with a GPU and no Mesa surfaceless support: try the device platform.
      display_ = open_device_display();
      if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor))
        throw GlError("EGL: no surfaceless or device display could be initialised");
    }
    if (!eglBindAPI(EGL_OPENGL_API)) throw GlError("EGL: eglBindAPI(EGL_OPENGL_API) failed");

    const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                     EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display_, config_attribs, &config, 1, &count) || count == 0) {
      // Surfaceless displays may expose configs without pbuffer support.
      const EGLint any[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
      if (!eglChooseConfig(display_, any, &config, 1, &count) || count == 0) config = nullptr;
    }
    const EGLint ctx_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                  EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                  EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, ctx_attribs);
    if (context_ == EGL_NO_CONTEXT)
      throw GlError("EGL: could not create an OpenGL 4.5 core context (error 0x" +
                    hex(eglGetError()) + ")");
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw GlError("EGL: eglMakeCurrent without a surface failed");
    read_strings();
    ++live_contexts();
  }

  ~EglContext() override {
    if (display_ == EGL_NO_DISPLAY) return;
    if (eglGetCurrentContext() == context_) eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    // Every context of the process shares the display, and terminating it
    // would end the others too: the last one terminates it.
    if (--live_contexts() == 0) eglTerminate(display_);
  }

  bool headless() const override { return true; }
  bool should_close() override { return false; }
  void present(unsigned, int, int) override {}
  void make_current() override {
    if (eglGetCurrentContext() != context_ && !eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw GlError("EGL: eglMakeCurrent of this context failed (error 0x" + hex(eglGetError()) + ")");
  }

 private:
  static std::string hex(EGLint v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%x", unsigned(v));
    return buf;
  }

  static std::atomic<int>& live_contexts() {
    static std::atomic<int> n{0};
    return n;
  }

  static EGLDisplay open_device_display() {
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration")) return EGL_NO_DISPLAY;
    EGLDeviceEXT devices[8];
    EGLint n = 0;
    if (!eglQueryDevicesEXT(8, devices, &n) || n == 0) return EGL_NO_DISPLAY;
    return eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
  }

  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> create_headless_context() { return std::make_unique<EglContext>(); }

}  // namespace ig::gl
