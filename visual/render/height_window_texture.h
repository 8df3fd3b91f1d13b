#pragma once
// Full-resolution heights around a point, for DEMs larger than one GL
// texture: a size x size R32F texture holding the window
// terrain::ToroidalWindow describes, addressed wrap-around (sample (i, j) in
// texel (i mod size, j mod size), GL_REPEAT), so a shader reads sample s at
// texel coordinate (s + 0.5) / size while s is inside the window, with
// linear filtering correct across the wrap seam. Moving the window uploads
// only the rows and columns that scrolled in (glTextureSubImage2D straight
// from the heightfield's rows, no staging copy; for paged heights, copied
// out of the tile cache, whose background thread is asked every move for the
// window and one tile around it, so the rows that scroll in are resident).
// The wrap-around texture itself is render/window_texture.h.

#include <epoxy/gl.h>

#include <glm/vec2.hpp>

#include <vector>

#include "render/window_texture.h"
#include "terrain/heightfield.h"

namespace ig::render {

class HeightWindowTexture {
 public:
  // hf must outlive the texture. size is clamped to the DEM (and must fit
  // the GL texture limit; throws gl::GlError otherwise).
  HeightWindowTexture(const terrain::Heightfield& hf, int size);

  // Moves the window so it is centred on sample `centre` (clamped to the
  // DEM) and uploads what scrolled in; returns the samples uploaded (0 when
  // it did not move).
  long long centre_on(glm::ivec2 centre);
  // Paged heights: asks the tile cache's background thread for the window
  // centred on `centre` and one tile around it (centre_on does it too).
  void prefetch_around(glm::ivec2 centre) const;

  // Where the window's first sample would be, centred on `centre`.
  glm::ivec2 origin_for(glm::ivec2 centre) const { return tex_.window().origin_for(centre); }
  GLuint id() const { return tex_.id(); }
  bool placed() const { return tex_.placed(); }  // centred at least once
  glm::ivec2 origin() const { return tex_.origin(); }
  glm::ivec2 size() const { return tex_.size(); }
  long long uploaded_samples() const { return tex_.uploaded_texels(); }

 private:
  const terrain::Heightfield& hf_;
  WindowTexture tex_;
  std::vector<float> staging_;  // paged heights: one rectangle out of the tile cache
};

}  // namespace ig::render
