#include "render/height_window_texture.h"

#include <string>

#include "gl/gl_context.h"
#include "gl/work_counters.h"
#include "terrain/paged_heights.h"

namespace ig::render {

HeightWindowTexture::HeightWindowTexture(const terrain::Heightfield& hf, int size)
    : hf_(hf), window_(hf.width, hf.height, size) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (window_.size_x() > max_size || window_.size_y() > max_size)
    throw gl::GlError(hf.source + ": height window " + std::to_string(window_.size_x()) + "x" +
                      std::to_string(window_.size_y()) + " exceeds the GL texture limit " + std::to_string(max_size));
  tex_ = gl::create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(tex_.id(), 1, GL_R32F, window_.size_x(), window_.size_y());
  glTextureParameteri(tex_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(tex_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // Wrap-around addressing: the texel after the last is the first, which
  // holds the next sample of the window in the DEM.
  glTextureParameteri(tex_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(tex_.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
}

void HeightWindowTexture::prefetch_around(glm::ivec2 centre) const {
  if (!hf_.paged) return;
  const glm::ivec2 o = window_.origin_for(centre);
  const int margin = hf_.paged->cache->tile_size();
  hf_.paged->cache->request(o.x - margin, o.y - margin, window_.size_x() + 2 * margin,
                            window_.size_y() + 2 * margin);
}

long long HeightWindowTexture::centre_on(glm::ivec2 centre) {
  prefetch_around(centre);
  const glm::ivec2 to = window_.origin_for(centre);
  if (window_.placed() && to == window_.origin()) return 0;
  long long samples = 0;
  const terrain::HeightTileCache* pages = hf_.paged ? hf_.paged->cache.get() : nullptr;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  // Whole heights: sub-rectangles of the heightfield in place; paged: each
  // rectangle copied out of the tile cache first.
  glPixelStorei(GL_UNPACK_ROW_LENGTH, pages ? 0 : hf_.width);
  for (const terrain::SampleRect& r : window_.move_to(to))
    for (const terrain::SampleRect& p : window_.split_at_seams(r)) {
      const glm::ivec2 slot = window_.slot({p.x, p.y});
      const float* src = nullptr;
      if (pages) {
        staging_.resize(static_cast<std::size_t>(p.w) * p.h);
        pages->read_rect(p.x, p.y, p.w, p.h, staging_.data(), p.w);
        src = staging_.data();
      } else {
        src = hf_.heights.data() + static_cast<std::size_t>(p.y) * hf_.width + p.x;
      }
      glTextureSubImage2D(tex_.id(), 0, slot.x, slot.y, p.w, p.h, GL_RED, GL_FLOAT, src);
      samples += p.samples();
    }
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  gl::count_upload(static_cast<std::uint64_t>(samples) * sizeof(float));
  uploaded_ += samples;
  return samples;
}

}  // namespace ig::render
