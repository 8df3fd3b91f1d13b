// Height window texture: a small toroidally addressed window,
// moved along a path with small steps, diagonal steps, seam crossings,
// clamping at the DEM's edges and jumps, holds after every move exactly the
// heights the full-DEM texture holds at the same samples, and each move
// uploads only what scrolled in.

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "gl/frame_state.h"
#include "gl/gl_context.h"
#include "gl/gl_objects.h"
#include "gl/window_storage.h"
#include "render/height_window_texture.h"
#include "terrain/heightfield.h"
#include "window_path_checks.h"

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

TEST(HeightWindowTexture, ToroidalUpdatesMatchTheFullTexture) {
  const auto context = ig::gl::create_headless_context();
  const ig::terrain::Heightfield hf = random_heightfield(97, 75);
  // The full texture, as TerrainScene makes it for a DEM that fits.
  const ig::gl::Texture full =
      ig::gl::create_filled_texture(hf.width, hf.height, ig::gl::kHeightTexels, hf.heights.data());
  const std::vector<float> full_texels = ig::gl::read_height_texels(full.id(), hf.width, hf.height);

  constexpr int kSize = 16;
  ig::render::HeightWindowTexture window(hf, kSize);
  ASSERT_EQ(window.size(), glm::ivec2(kSize, kSize));
  const long long total = window_checks::expect_window_follows_path<float>(
      kSize, hf.width, full_texels, 1, [&](glm::ivec2 c) { return window.centre_on(c); },
      [&] { return window.origin(); }, [&] { return ig::gl::read_height_texels(window.id(), kSize, kSize); },
      [&](glm::ivec2, glm::ivec2 o) {
        EXPECT_GE(o.x, 0);
        EXPECT_GE(o.y, 0);
        EXPECT_LE(o.x + kSize, hf.width);
        EXPECT_LE(o.y + kSize, hf.height);
      });
  EXPECT_EQ(window.uploaded_samples(), total);
  EXPECT_TRUE(ig::gl::no_gl_error());
}

}  // namespace
