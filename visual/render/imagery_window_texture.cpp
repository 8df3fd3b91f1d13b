#include "render/imagery_window_texture.h"

#include <stdexcept>

namespace ig::render {
namespace {
const terrain::Imagery& checked(const terrain::Imagery& imagery) {
  if (!imagery.paged || !imagery.paged->cache)
    throw std::invalid_argument("ImageryWindowTexture: the imagery has no full-resolution pages");
  return imagery;
}
}  // namespace

ImageryWindowTexture::ImageryWindowTexture(const terrain::Imagery& imagery, int dem_w, int dem_h, int size,
                                           const std::string& what)
    : pages_(checked(imagery).paged),
      full_w_(imagery.full_width()),
      full_h_(imagery.full_height()),
      dem_w_(dem_w),
      dem_h_(dem_h),
      tex_(full_w_, full_h_, size, gl::kImageryTexels, what) {}

long long ImageryWindowTexture::centre_on_sample(glm::ivec2 centre, bool wait) {
  // Sample s is at texture coordinate (s + 0.5) / dem_size, as in the shaders.
  const glm::ivec2 pixel{int((centre.x + 0.5) * full_w_ / dem_w_), int((centre.y + 0.5) * full_h_ / dem_h_)};
  const terrain::RgbTileCache& cache = *pages_->cache;
  const glm::ivec2 to = tex_.window().origin_for(pixel), s = size();
  const int margin = cache.tile_size();
  cache.request(to.x - margin, to.y - margin, s.x + 2 * margin, s.y + 2 * margin);
  if (tex_.placed() && to == tex_.origin()) return 0;
  // What the move would bring in, copied out of the cache first: all of it
  // or (not waiting, a tile not resident) nothing, and the window stays.
  terrain::ToroidalWindow probe = tex_.window();
  const std::vector<terrain::SampleRect> rects = probe.move_to(to);
  staged_.resize(rects.size());
  int missing = 0;
  for (std::size_t i = 0; i < rects.size(); ++i) {
    const terrain::SampleRect& r = rects[i];
    staged_[i].resize(static_cast<std::size_t>(r.samples()));
    if (wait)
      cache.read_rect(r.x, r.y, r.w, r.h, staged_[i].data(), r.w);
    else
      missing += cache.try_read_rect(r.x, r.y, r.w, r.h, staged_[i].data(), r.w);
  }
  if (missing > 0) {
    ++stats_.held_moves;
    stats_.missing_tiles += missing;
    return 0;
  }
  ++stats_.moves;
  const long long uploaded = tex_.centre_on(pixel, [&](const terrain::SampleRect& p) -> WindowTexture::Rows {
    // p is a piece of one of the rectangles (split at the wrap-around seams).
    for (std::size_t i = 0; i < rects.size(); ++i) {
      const terrain::SampleRect& r = rects[i];
      if (p.x >= r.x && p.y >= r.y && p.x + p.w <= r.x + r.w && p.y + p.h <= r.y + r.h)
        return {staged_[i].data() + static_cast<std::size_t>(p.y - r.y) * r.w + (p.x - r.x), r.w};
    }
    throw std::logic_error("ImageryWindowTexture: a piece outside the move's rectangles");
  });
  for (auto& v : staged_)  // a whole-window fill is 50 MB: not kept for the small moves after it
    if (v.capacity() > (std::size_t(1) << 20)) std::vector<terrain::Rgb8>().swap(v);
  return uploaded;
}

}  // namespace ig::render
