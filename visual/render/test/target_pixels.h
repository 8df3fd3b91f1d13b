#pragma once
// A render target read back to the CPU, as the GL tests' frames hold it:
// its size, depth (top row first; 0 = sky) and RGBA.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gl/render_target.h"

struct TargetPixels {
  int w = 0, h = 0;
  std::vector<float> depth;
  std::vector<std::uint8_t> rgba;

  bool terrain(int x, int y) const { return depth[std::size_t(y) * w + x] > 0.0f; }
  void read(const ig::gl::RenderTarget& target) {
    w = target.width();
    h = target.height();
    depth = target.read_depth();
    rgba = target.read_rgba();
  }
};
