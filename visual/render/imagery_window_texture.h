#pragma once
// Full-resolution imagery around a point, for imagery finer than one GL
// texture (issue 16): the scene draws an overview of the image everywhere
// and this size x size RGB8 wrap-around window (render/window_texture.h) of
// the full image where it covers a fragment. It follows the same point as
// the height window (Level1's centre, in DEM samples); a move uploads only
// the imagery rows and columns that scrolled in, from the full image held in
// memory (terrain/imagery_loader.h).

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "render/window_texture.h"
#include "terrain/imagery_loader.h"

namespace ig::render {

class ImageryWindowTexture {
 public:
  // Takes imagery.full_rgb (full_width() x full_height(), over the footprint
  // of a dem_w x dem_h DEM). Throws gl::GlError if size does not fit GL.
  ImageryWindowTexture(terrain::Imagery& imagery, int dem_w, int dem_h, int size, const std::string& what);

  // Centres the window on the imagery under DEM sample `centre`; returns the
  // pixels uploaded (0 when it did not move).
  long long centre_on_sample(glm::ivec2 centre);

  GLuint id() const { return tex_.id(); }
  bool placed() const { return tex_.placed(); }
  glm::ivec2 origin() const { return tex_.origin(); }  // in full-resolution pixels
  glm::ivec2 size() const { return tex_.size(); }
  glm::ivec2 full_size() const { return {full_w_, full_h_}; }
  long long uploaded_pixels() const { return tex_.uploaded_texels(); }

 private:
  std::vector<std::uint8_t> rgb_;  // full resolution, row 0 = south
  int full_w_, full_h_, dem_w_, dem_h_;
  WindowTexture tex_;
};

}  // namespace ig::render
