#include "render/window_texture.h"

#include "gl/gl_context.h"
#include "gl/work_counters.h"

namespace ig::render {

WindowTexture::WindowTexture(int grid_w, int grid_h, int size, const WindowTexelFormat& format,
                             const std::string& what)
    : window_(grid_w, grid_h, size), format_(format) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (window_.size_x() > max_size || window_.size_y() > max_size)
    throw gl::GlError(what + " " + std::to_string(window_.size_x()) + "x" + std::to_string(window_.size_y()) +
                      " exceeds the GL texture limit " + std::to_string(max_size));
  tex_ = gl::create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(tex_.id(), 1, format_.internal_format, window_.size_x(), window_.size_y());
  glTextureParameteri(tex_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(tex_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // Wrap-around addressing: the texel after the last is the first, which
  // holds the next texel of the window in the grid.
  glTextureParameteri(tex_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(tex_.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
}

long long WindowTexture::centre_on(glm::ivec2 centre, const Source& source) {
  const glm::ivec2 to = window_.origin_for(centre);
  if (window_.placed() && to == window_.origin()) return 0;
  long long texels = 0;
  glPixelStorei(GL_UNPACK_ALIGNMENT, format_.unpack_alignment);
  for (const terrain::SampleRect& r : window_.move_to(to))
    for (const terrain::SampleRect& p : window_.split_at_seams(r)) {
      const glm::ivec2 slot = window_.slot({p.x, p.y});
      const Rows rows = source(p);
      glPixelStorei(GL_UNPACK_ROW_LENGTH, rows.row_length);
      glTextureSubImage2D(tex_.id(), 0, slot.x, slot.y, p.w, p.h, format_.format, format_.type, rows.data);
      texels += p.samples();
    }
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  gl::count_upload(static_cast<std::uint64_t>(texels) * format_.bytes_per_texel);
  uploaded_ += texels;
  return texels;
}

}  // namespace ig::render
