// Height window texture (issue 16): a small toroidally addressed window,
// moved along a path with small steps, diagonal steps, seam crossings,
// clamping at the DEM's edges and jumps, holds after every move exactly the
// heights the full-DEM texture holds at the same samples, and each move
// uploads only what scrolled in.

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include <epoxy/gl.h>

#include <glm/common.hpp>

#include "gl/gl_context.h"
#include "gl/gl_objects.h"
#include "render/height_window_texture.h"
#include "terrain/heightfield.h"

namespace {

ig::terrain::Heightfield random_heightfield(int w, int h) {
  ig::terrain::Heightfield hf;
  hf.width = w;
  hf.height = h;
  hf.heights.resize(static_cast<std::size_t>(w) * h);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-500.f, 4500.f);
  for (float& v : hf.heights) v = u(rng);
  hf.finalize_stats();
  hf.source = "random";
  return hf;
}

std::vector<float> read_texture(GLuint tex, int w, int h) {
  std::vector<float> out(static_cast<std::size_t>(w) * h);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(tex, 0, GL_RED, GL_FLOAT, static_cast<GLsizei>(out.size() * sizeof(float)), out.data());
  return out;
}

TEST(HeightWindowTexture, ToroidalUpdatesMatchTheFullTexture) {
  const auto context = ig::gl::create_headless_context();
  const ig::terrain::Heightfield hf = random_heightfield(97, 75);
  // The full texture, as TerrainScene makes it for a DEM that fits.
  ig::gl::Texture full = ig::gl::create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(full.id(), 1, GL_R32F, hf.width, hf.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(full.id(), 0, 0, 0, hf.width, hf.height, GL_RED, GL_FLOAT, hf.heights.data());
  const std::vector<float> full_texels = read_texture(full.id(), hf.width, hf.height);

  constexpr int kSize = 16;
  ig::render::HeightWindowTexture window(hf, kSize);
  ASSERT_EQ(window.size(), glm::ivec2(kSize, kSize));
  const std::vector<glm::ivec2> path = {{40, 30}, {41, 30}, {41, 31}, {44, 35}, {43, 34}, {30, 20}, {31, 21},
                                        {0, 0},   {3, 2},   {96, 74}, {90, 70}, {50, 40}, {52, 37}, {48, 44},
                                        {63, 47}, {64, 48}, {79, 63}, {60, 30}, {60, 30}};
  long long expected_total = 0;
  glm::ivec2 prev{};
  bool first = true;
  for (const glm::ivec2 c : path) {
    SCOPED_TRACE(testing::Message() << "centre " << c.x << "," << c.y);
    const long long uploaded = window.centre_on(c);
    const glm::ivec2 o = window.origin();
    // Only what scrolled in: the window's area minus its overlap with the last one.
    const glm::ivec2 d = first ? glm::ivec2(kSize) : glm::abs(o - prev);
    const long long overlap = static_cast<long long>(std::max(kSize - d.x, 0)) * std::max(kSize - d.y, 0);
    EXPECT_EQ(uploaded, first ? kSize * kSize : kSize * kSize - overlap);
    expected_total += uploaded;
    first = false;
    prev = o;
    EXPECT_GE(o.x, 0);
    EXPECT_GE(o.y, 0);
    EXPECT_LE(o.x + kSize, hf.width);
    EXPECT_LE(o.y + kSize, hf.height);
    const std::vector<float> texels = read_texture(window.id(), kSize, kSize);
    for (int j = o.y; j < o.y + kSize; ++j)
      for (int i = o.x; i < o.x + kSize; ++i)
        ASSERT_EQ(texels[static_cast<std::size_t>(j % kSize) * kSize + i % kSize],
                  full_texels[static_cast<std::size_t>(j) * hf.width + i])
            << "sample " << i << "," << j;
  }
  EXPECT_EQ(window.uploaded_samples(), expected_total);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
