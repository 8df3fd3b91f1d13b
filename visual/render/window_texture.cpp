#include "render/window_texture.h"

#include "gl/work_counters.h"

namespace ig::render {

WindowTexture::WindowTexture(int grid_w, int grid_h, int size, const gl::TexelFormat& format,
                             const std::string& what)
    : window_(grid_w, grid_h, size), storage_(window_.size_x(), window_.size_y(), format, what) {}

long long WindowTexture::centre_on(glm::ivec2 centre, const Source& source) {
  const glm::ivec2 to = window_.origin_for(centre);
  if (window_.placed() && to == window_.origin()) return 0;
  long long texels = 0;
  for (const terrain::SampleRect& r : window_.move_to(to))
    for (const terrain::SampleRect& p : window_.split_at_seams(r)) {
      const glm::ivec2 slot = window_.slot({p.x, p.y});
      const Rows rows = source(p);
      storage_.upload(slot.x, slot.y, p.w, p.h, rows.data, rows.row_length);
      texels += p.samples();
    }
  gl::count_upload(static_cast<std::uint64_t>(texels) * storage_.format().bytes_per_texel);
  uploaded_ += texels;
  return texels;
}

}  // namespace ig::render
