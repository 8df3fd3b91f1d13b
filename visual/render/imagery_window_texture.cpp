#include "render/imagery_window_texture.h"

#include <utility>

namespace ig::render {

ImageryWindowTexture::ImageryWindowTexture(terrain::Imagery& imagery, int dem_w, int dem_h, int size,
                                           const std::string& what)
    : rgb_(std::move(imagery.full_rgb)),
      full_w_(imagery.full_width()),
      full_h_(imagery.full_height()),
      dem_w_(dem_w),
      dem_h_(dem_h),
      tex_(full_w_, full_h_, size, {GL_RGB8, GL_RGB, GL_UNSIGNED_BYTE, 3, 1}, what) {}

long long ImageryWindowTexture::centre_on_sample(glm::ivec2 centre) {
  // Sample s is at texture coordinate (s + 0.5) / dem_size, as in the shaders.
  const glm::ivec2 pixel{int((centre.x + 0.5) * full_w_ / dem_w_), int((centre.y + 0.5) * full_h_ / dem_h_)};
  return tex_.centre_on(pixel, [&](const terrain::SampleRect& r) -> WindowTexture::Rows {
    return {rgb_.data() + (static_cast<std::size_t>(r.y) * full_w_ + r.x) * 3, full_w_};
  });
}

}  // namespace ig::render
