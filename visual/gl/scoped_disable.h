#pragma once
// Turns a GL capability off for a scope and restores its previous state,
// e.g. face culling around geometry seen from both sides (skirts, walls,
// full-screen passes).

#include <epoxy/gl.h>

namespace ig::gl {

class ScopedDisable {
 public:
  explicit ScopedDisable(GLenum capability) : capability_(capability), was_enabled_(glIsEnabled(capability)) {
    glDisable(capability_);
  }
  ~ScopedDisable() {
    if (was_enabled_) glEnable(capability_);
  }
  ScopedDisable(const ScopedDisable&) = delete;
  ScopedDisable& operator=(const ScopedDisable&) = delete;

 private:
  GLenum capability_;
  bool was_enabled_;
};

}  // namespace ig::gl
