#pragma once
// A texture holding a square window over a grid too large for one texture
// (DEM samples, imagery pixels), addressed wrap-around: grid texel (i, j)
// lives in texel (i mod size, j mod size), and the texture repeats, so linear
// filtering is right across the seam. terrain::ToroidalWindow says which
// rectangles scroll in on a move; only those are uploaded, straight from the
// caller's rows, no copy (gl/window_storage.h). No mipmaps: a shader reads
// it at level 0 only. Shared by the height and imagery windows.

#include <functional>
#include <string>

#include <glm/vec2.hpp>

#include "gl/window_storage.h"
#include "terrain/toroidal_window.h"

namespace ig::render {

class WindowTexture {
 public:
  // Where a rectangle's texels come from: its first texel and the row length
  // (in texels) of the buffer it lies in. Valid until the next call.
  struct Rows {
    const void* data;
    int row_length;
  };
  using Source = std::function<Rows(const terrain::SampleRect&)>;

  // A size x size window (clamped to the grid) over grid_w x grid_h. Throws
  // gl::GlError "<what> WxH exceeds the GL texture limit N" if it does not fit.
  WindowTexture(int grid_w, int grid_h, int size, const gl::TexelFormat& format, const std::string& what);

  // Moves the window so it is centred on `centre` (clamped to the grid) and
  // uploads what scrolled in from `source`; returns the texels uploaded.
  long long centre_on(glm::ivec2 centre, const Source& source);

  const terrain::ToroidalWindow& window() const { return window_; }
  unsigned id() const { return storage_.id(); }  // the GL texture name
  bool placed() const { return window_.placed(); }
  glm::ivec2 origin() const { return window_.origin(); }
  glm::ivec2 size() const { return {window_.size_x(), window_.size_y()}; }
  long long uploaded_texels() const { return uploaded_; }

 private:
  terrain::ToroidalWindow window_;
  gl::WindowStorage storage_;
  long long uploaded_ = 0;
};

}  // namespace ig::render
