// Imagery window texture (issue 16): a small wrap-around window over
// full-resolution imagery (2 pixels a DEM sample), moved along a path of
// small, diagonal, seam-crossing, clamped and jumping steps, holds after
// every move exactly the pixels a full upload of the image holds, and each
// move uploads only what scrolled in.

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include <epoxy/gl.h>

#include <glm/common.hpp>

#include "gl/gl_context.h"
#include "gl/gl_objects.h"
#include "render/imagery_window_texture.h"
#include "terrain/imagery_loader.h"

namespace {

std::vector<std::uint8_t> read_rgb(GLuint tex, int w, int h) {
  std::vector<std::uint8_t> out(static_cast<std::size_t>(w) * h * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(tex, 0, GL_RGB, GL_UNSIGNED_BYTE, static_cast<GLsizei>(out.size()), out.data());
  return out;
}

TEST(ImageryWindowTexture, ToroidalUpdatesMatchAFullUpload) {
  const auto context = ig::gl::create_headless_context();
  constexpr int kDemW = 97, kDemH = 75, kStep = 2, kSize = 24;
  ig::terrain::Imagery img;
  img.width = kDemW;
  img.height = kDemH;
  img.full_step = kStep;
  img.full_w = kDemW * kStep;
  img.full_h = kDemH * kStep;
  const int fw = img.full_width(), fh = img.full_height();
  img.full_rgb.resize(static_cast<std::size_t>(fw) * fh * 3);
  std::mt19937 rng(11);
  for (auto& v : img.full_rgb) v = std::uint8_t(rng());
  // The full image in one texture, as the scene makes it when it fits.
  ig::gl::Texture full = ig::gl::create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(full.id(), 1, GL_RGB8, fw, fh);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(full.id(), 0, 0, 0, fw, fh, GL_RGB, GL_UNSIGNED_BYTE, img.full_rgb.data());
  const std::vector<std::uint8_t> full_texels = read_rgb(full.id(), fw, fh);

  ig::render::ImageryWindowTexture window(img, kDemW, kDemH, kSize, "test imagery window");
  ASSERT_EQ(window.size(), glm::ivec2(kSize, kSize));
  ASSERT_EQ(window.full_size(), glm::ivec2(fw, fh));
  const std::vector<glm::ivec2> path = {{40, 30}, {41, 30}, {41, 31}, {44, 35}, {43, 34}, {30, 20}, {31, 21},
                                        {0, 0},   {3, 2},   {96, 74}, {90, 70}, {50, 40}, {52, 37}, {48, 44},
                                        {63, 47}, {64, 48}, {79, 63}, {60, 30}, {60, 30}};
  glm::ivec2 prev{};
  bool first = true;
  for (const glm::ivec2 c : path) {
    SCOPED_TRACE(testing::Message() << "sample " << c.x << "," << c.y);
    const long long uploaded = window.centre_on_sample(c);
    const glm::ivec2 o = window.origin();
    const glm::ivec2 d = first ? glm::ivec2(kSize) : glm::abs(o - prev);
    const long long overlap = static_cast<long long>(std::max(kSize - d.x, 0)) * std::max(kSize - d.y, 0);
    EXPECT_EQ(uploaded, first ? kSize * kSize : kSize * kSize - overlap);
    first = false;
    prev = o;
    // Centred on the sample's pixel, unless clamped at the image's edges.
    const glm::ivec2 centre_px = (2 * c + 1) * kStep / 2;
    EXPECT_EQ(o.x, std::clamp(centre_px.x - kSize / 2, 0, fw - kSize));
    EXPECT_EQ(o.y, std::clamp(centre_px.y - kSize / 2, 0, fh - kSize));
    const std::vector<std::uint8_t> texels = read_rgb(window.id(), kSize, kSize);
    for (int j = o.y; j < o.y + kSize; ++j)
      for (int i = o.x; i < o.x + kSize; ++i)
        for (int k = 0; k < 3; ++k)
          ASSERT_EQ(texels[(static_cast<std::size_t>(j % kSize) * kSize + i % kSize) * 3 + k],
                    full_texels[(static_cast<std::size_t>(j) * fw + i) * 3 + k])
              << "pixel " << i << "," << j;
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
