#include "render/height_window_texture.h"

#include <string>

#include "gl/gl_context.h"
#include "gl/work_counters.h"

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

long long HeightWindowTexture::centre_on(glm::ivec2 centre) {
  const glm::ivec2 to = window_.origin_for(centre);
  if (window_.placed() && to == window_.origin()) return 0;
  long long samples = 0;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, hf_.width);  // read sub-rectangles of the heightfield in place
  for (const terrain::SampleRect& r : window_.move_to(to))
    for (const terrain::SampleRect& p : window_.split_at_seams(r)) {
      const glm::ivec2 slot = window_.slot({p.x, p.y});
      glTextureSubImage2D(tex_.id(), 0, slot.x, slot.y, p.w, p.h, GL_RED, GL_FLOAT,
                          hf_.heights.data() + static_cast<std::size_t>(p.y) * hf_.width + p.x);
      samples += p.samples();
    }
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  gl::count_upload(static_cast<std::uint64_t>(samples) * sizeof(float));
  uploaded_ += samples;
  return samples;
}

}  // namespace ig::render
