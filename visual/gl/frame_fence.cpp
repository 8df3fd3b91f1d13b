#include "gl/frame_fence.h"

#include <epoxy/gl.h>

namespace ig::gl {
namespace {
GLsync as_sync(void* p) { return static_cast<GLsync>(p); }
}  // namespace

FrameFence& FrameFence::operator=(FrameFence&& o) noexcept {
  if (this != &o) {
    if (sync_) glDeleteSync(as_sync(sync_));
    sync_ = o.sync_;
    o.sync_ = nullptr;
  }
  return *this;
}

FrameFence::~FrameFence() {
  if (sync_) glDeleteSync(as_sync(sync_));
}

FrameFence FrameFence::after_issued_work() {
  FrameFence f;
  f.sync_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  glFlush();
  return f;
}

bool FrameFence::done() const {
  if (!sync_) return true;
  const GLenum r = glClientWaitSync(as_sync(sync_), 0, 0);
  return r == GL_ALREADY_SIGNALED || r == GL_CONDITION_SATISFIED || r == GL_WAIT_FAILED;
}

void FrameFence::wait() const {
  if (!sync_) return;
  constexpr GLuint64 kSecond = 1'000'000'000;
  for (;;) {
    const GLenum r = glClientWaitSync(as_sync(sync_), GL_SYNC_FLUSH_COMMANDS_BIT, kSecond);
    if (r != GL_TIMEOUT_EXPIRED) return;  // signalled, or an error (a lost context): nothing to wait for
  }
}

}  // namespace ig::gl
