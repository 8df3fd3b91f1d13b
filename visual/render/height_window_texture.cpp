#include "render/height_window_texture.h"

#include "terrain/paged_heights.h"

namespace ig::render {

HeightWindowTexture::HeightWindowTexture(const terrain::Heightfield& hf, int size)
    : hf_(hf), tex_(hf.width, hf.height, size, gl::kHeightTexels, hf.source + ": height window") {}

void HeightWindowTexture::prefetch_around(glm::ivec2 centre) const {
  if (!hf_.paged) return;
  const glm::ivec2 o = origin_for(centre);
  const int margin = hf_.paged->cache->tile_size();
  const glm::ivec2 s = size();
  hf_.paged->cache->request(o.x - margin, o.y - margin, s.x + 2 * margin, s.y + 2 * margin);
}

long long HeightWindowTexture::centre_on(glm::ivec2 centre) {
  prefetch_around(centre);
  const terrain::HeightTileCache* pages = hf_.paged ? hf_.paged->cache.get() : nullptr;
  // Whole heights: sub-rectangles of the heightfield in place; paged: each
  // rectangle copied out of the tile cache first.
  return tex_.centre_on(centre, [&](const terrain::SampleRect& p) -> WindowTexture::Rows {
    if (!pages) return {hf_.heights.data() + static_cast<std::size_t>(p.y) * hf_.width + p.x, hf_.width};
    staging_.resize(static_cast<std::size_t>(p.w) * p.h);
    pages->read_rect(p.x, p.y, p.w, p.h, staging_.data(), p.w);
    return {staging_.data(), p.w};
  });
}

}  // namespace ig::render
