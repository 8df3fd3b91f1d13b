// Imagery window texture: a small wrap-around window over
// full-resolution imagery (2 pixels a DEM sample) paged through a tile
// cache, moved along a path of small, diagonal, seam-crossing, clamped and
// jumping steps, holds after every move exactly the pixels a full upload of
// the image holds, and each move uploads only what scrolled in; a move whose
// tiles are not resident is held (never waits) and made once they are; the
// window of real imagery paged from GDAL equals the in-memory warp's pixels.

#include <gtest/gtest.h>

#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <condition_variable>
#include <filesystem>
#include <memory>
#include <mutex>
#include <random>
#include <vector>

#include "gl/frame_state.h"
#include "gl/gl_context.h"
#include "gl/gl_objects.h"
#include "gl/window_storage.h"
#include "render/imagery_window_texture.h"
#include "render/terrain_scene.h"
#include "terrain/imagery_loader.h"
#include "terrain/test/imagery_test_data.h"
#include "window_path_checks.h"

namespace {

std::vector<std::uint8_t> upload_and_read(const std::vector<std::uint8_t>& rgb, int w, int h) {
  const ig::gl::Texture full = ig::gl::create_filled_texture(w, h, ig::gl::kImageryTexels, rgb.data());
  return ig::gl::read_imagery_texels(full.id(), w, h);
}

// Lets the test stop the cache's reads (so tiles stay missing) and go on.
struct Gate {
  std::mutex m;
  std::condition_variable cv;
  bool open = true;
  void set(bool o) {
    {
      std::lock_guard lock(m);
      open = o;
    }
    cv.notify_all();
  }
};

// Paged imagery over a dem_w x dem_h DEM at `step` pixels a sample, read
// from `rgb` (south row first) through a tile cache.
ig::terrain::Imagery paged_imagery(int dem_w, int dem_h, int step, std::shared_ptr<const std::vector<std::uint8_t>> rgb,
                                   int tile, std::size_t budget, std::shared_ptr<Gate> gate) {
  ig::terrain::Imagery img;
  img.width = dem_w;
  img.height = dem_h;
  img.full_step = step;
  img.full_w = dem_w * step;
  img.full_h = dem_h * step;
  const int fw = img.full_w;
  auto pages = std::make_shared<ig::terrain::PagedImagery>();
  pages->cache = std::make_shared<const ig::terrain::RgbTileCache>(
      img.full_w, img.full_h, tile, budget, [=](int, int, int x0, int y0, int w, int h, ig::terrain::Rgb8* out) {
        std::unique_lock lock(gate->m);
        gate->cv.wait(lock, [&] { return gate->open; });
        for (int r = 0; r < h; ++r)
          for (int c = 0; c < w; ++c) {
            const std::uint8_t* p = rgb->data() + (static_cast<std::size_t>(y0 + r) * fw + x0 + c) * 3;
            out[r * w + c] = {p[0], p[1], p[2]};
          }
      });
  img.paged = pages;
  return img;
}

// An fw x fh RGB8 image of random pixels.
std::shared_ptr<std::vector<std::uint8_t>> random_rgb(int fw, int fh, unsigned seed) {
  auto rgb = std::make_shared<std::vector<std::uint8_t>>(static_cast<std::size_t>(fw) * fh * 3);
  std::mt19937 rng(seed);
  for (auto& v : *rgb) v = std::uint8_t(rng());
  return rgb;
}

// A 24-pixel window over random imagery of a 97 x 75 DEM at 2 pixels a
// sample, paged in tiles of 8 through a cache whose budget is what the
// window needs (so the path's jumps evict), its reads stopped by `gate`;
// full_texels: the whole image uploaded as one texture, as the scene makes
// it when it fits.
struct RandomImageryWindow {
  static constexpr int kDemW = 97, kDemH = 75, kStep = 2, kSize = 24;
  static constexpr int fw = kDemW * kStep, fh = kDemH * kStep;
  std::unique_ptr<ig::gl::GlContext> context = ig::gl::create_headless_context();
  std::shared_ptr<Gate> gate = std::make_shared<Gate>();
  std::shared_ptr<std::vector<std::uint8_t>> rgb;
  std::vector<std::uint8_t> full_texels;
  ig::render::ImageryWindowTexture window;

  explicit RandomImageryWindow(unsigned seed)
      : rgb(random_rgb(fw, fh, seed)),
        full_texels(upload_and_read(*rgb, fw, fh)),
        window(paged_imagery(kDemW, kDemH, kStep, rgb, 8, ig::terrain::imagery_window_budget(kSize, 8), gate), kDemW,
               kDemH, kSize, "test imagery window") {}
};

// A GeoTIFF 3x finer than a 61 x 49 DEM, tiled, written as `name` (removed
// again on destruction), and the one-texture in-memory warp of it.
struct RealImagery {
  ig::terrain::Heightfield hf = imagery_test::dem(61, 49);
  std::string path;
  ig::terrain::Imagery whole;
  std::vector<std::uint8_t> full_texels;

  explicit RealImagery(const std::string& name) {
    const double k = imagery_test::kRes;
    const double gt[6] = {-118.0 - 0.5 * k - 0.01, k / 3, 0, 37.0 + 0.5 * k + 0.01, 0, -k / 3};
    path = imagery_test::write_image(name, 4326, gt, 400, 400, /*tiled=*/true);
    whole = ig::terrain::load_imagery(hf, path, 16384);
    full_texels = upload_and_read(whole.rgb, whole.width, whole.height);
  }
  ~RealImagery() { std::filesystem::remove(path); }
};

TEST(ImageryWindowTexture, ToroidalUpdatesMatchAFullUpload) {
  RandomImageryWindow t(11);
  using W = RandomImageryWindow;
  constexpr int kStep = W::kStep, kSize = W::kSize, fw = W::fw, fh = W::fh;
  auto& window = t.window;
  ASSERT_EQ(window.size(), glm::ivec2(kSize, kSize));
  ASSERT_EQ(window.full_size(), glm::ivec2(fw, fh));
  const long long total = window_checks::expect_window_follows_path<std::uint8_t>(
      kSize, fw, t.full_texels, 3,
      [&](glm::ivec2 c) {
        // Moved at once if its tiles are resident, else held until they are
        // (the held case is the next test).
        const long long uploaded = window.centre_on_sample(c);
        window.cache().wait_idle();
        return uploaded + window.centre_on_sample(c);
      },
      [&] { return window.origin(); }, [&] { return ig::gl::read_imagery_texels(window.id(), kSize, kSize); },
      [&](glm::ivec2 c, glm::ivec2 o) {
        // Centred on the sample's pixel, unless clamped at the image's edges.
        const glm::ivec2 centre_px = (2 * c + 1) * kStep / 2;
        EXPECT_EQ(o.x, std::clamp(centre_px.x - kSize / 2, 0, fw - kSize));
        EXPECT_EQ(o.y, std::clamp(centre_px.y - kSize / 2, 0, fh - kSize));
      });
  EXPECT_EQ(window.uploaded_pixels(), total);
  EXPECT_EQ(window.cache().stats().misses, 0);  // no frame read a tile itself
  EXPECT_GT(window.cache().stats().evictions, 0);
  EXPECT_LE(window.cache().stats().peak_resident_bytes, window.cache().budget_bytes());
  EXPECT_TRUE(ig::gl::no_gl_error());
}

TEST(ImageryWindowTexture, AMoveWhoseTilesAreNotResidentIsHeldNotWaitedFor) {
  RandomImageryWindow t(5);
  using W = RandomImageryWindow;
  constexpr int kSize = W::kSize, fw = W::fw, fh = W::fh;
  auto& window = t.window;
  auto& gate = t.gate;
  const auto& cache = window.cache();
  EXPECT_EQ(window.centre_on_sample({20, 20}, /*wait=*/true), kSize * kSize);  // the first fill, at load
  cache.wait_idle();
  const long long load_misses = cache.stats().misses;
  const glm::ivec2 placed = window.origin();

  gate->set(false);  // the disk stalls
  EXPECT_EQ(window.centre_on_sample({80, 60}), 0);  // far: none of its tiles resident
  EXPECT_EQ(window.origin(), placed);
  EXPECT_EQ(window.stats().held_moves, 1);
  EXPECT_EQ(window.stats().missing_tiles, 16);  // origin 149,109: tiles 18..21 x 13..16
  EXPECT_EQ(window.centre_on_sample({80, 60}), 0);
  EXPECT_EQ(window.stats().held_moves, 2);
  EXPECT_EQ(window.centre_on_sample({20, 20}), 0);  // back where it is: nothing to do, nothing held
  EXPECT_EQ(window.stats().held_moves, 2);

  gate->set(true);
  // Asked again (moved now if the tiles came in already), then once they are in.
  long long uploaded = window.centre_on_sample({80, 60});
  cache.wait_idle();
  uploaded += window.centre_on_sample({80, 60});
  EXPECT_EQ(uploaded, kSize * kSize);  // a jump: the whole window, once
  const glm::ivec2 o = window.origin();
  EXPECT_EQ(o, glm::ivec2(std::clamp(161 - kSize / 2, 0, fw - kSize), std::clamp(121 - kSize / 2, 0, fh - kSize)));
  window_checks::expect_window_holds(ig::gl::read_imagery_texels(window.id(), kSize, kSize), kSize, o, t.full_texels, fw, 3);
  EXPECT_EQ(cache.stats().misses, load_misses);  // no move read a tile itself
  EXPECT_EQ(window.stats().moves, 2);
}

// Real imagery paged from GDAL (a GeoTIFF 3x finer than a 61 x 49 DEM,
// texture limit 50, a budget at the window's least): the window holds what
// the one-texture in-memory warp of the same image holds.
TEST(ImageryWindowTexture, PagedGdalImageryEqualsTheInMemoryWarp) {
  const auto context = ig::gl::create_headless_context();
  const RealImagery real("ig_imagery_window.tif");
  const auto& hf = real.hf;
  const auto& whole = real.whole;
  constexpr int kSize = 40;
  ig::terrain::ImageryPaging paging;
  paging.budget_bytes = 1;
  paging.tile = 16;
  paging.window_side = kSize;
  const auto img = ig::terrain::load_imagery(hf, real.path, 50, paging);
  ASSERT_TRUE(img.paged);
  ASSERT_EQ(img.full_width(), whole.width);
  ig::render::ImageryWindowTexture window(img, hf.width, hf.height, kSize, "test imagery window");
  for (const glm::ivec2 c : {glm::ivec2{30, 24}, {33, 25}, {5, 3}, {60, 48}, {40, 10}}) {
    SCOPED_TRACE(testing::Message() << "centre " << c.x << "," << c.y);
    window.centre_on_sample(c);
    window.cache().wait_idle();
    window.centre_on_sample(c);
    window_checks::expect_window_holds(ig::gl::read_imagery_texels(window.id(), kSize, kSize), kSize, window.origin(),
                                       real.full_texels, whole.width, 3);
  }
  EXPECT_GT(window.cache().stats().evictions, 0);
  EXPECT_EQ(window.failed_tiles(), 0);
}

// Every channel's window set gets its own imagery window over the same
// paged imagery (TerrainScene::claim_windows): two sets centred far apart
// each hold the in-memory warp's pixels around their own centre.
TEST(ImageryWindowTexture, EachWindowSetHasItsOwnImageryWindow) {
  const auto context = ig::gl::create_headless_context();
  const RealImagery real("ig_imagery_sets.tif");
  // Texture limit 50: heights and imagery beyond it, windows of 50.
  ig::render::TerrainScene scene(real.hf, ig::render::ShadingParams{}, real.path, 50);
  scene.set_wait_for_pages(true);  // moves read their tiles (no held moves to wait out)
  const int a = scene.claim_windows(), b = scene.claim_windows();
  ASSERT_NE(a, b);
  ASSERT_TRUE(scene.imagery_window(a) && scene.imagery_window(b));
  ASSERT_NE(scene.imagery_window(a)->id(), scene.imagery_window(b)->id());
  scene.follow_window(a, {8, 6});
  scene.follow_window(b, {52, 42});
  scene.follow_window(a, {8, 6});  // b's move left a where it was: nothing to upload
  const auto* wa = scene.imagery_window(a);
  const auto* wb = scene.imagery_window(b);
  EXPECT_GT(std::abs(wa->origin().x - wb->origin().x), 60);
  for (const auto* w : {wa, wb})
    window_checks::expect_window_holds(ig::gl::read_imagery_texels(w->id(), w->size().x, w->size().y), w->size().x, w->origin(),
                                       real.full_texels, real.whole.width, 3);
  EXPECT_EQ(wa->stats().moves, 1);
  scene.release_windows(b);
}

}  // namespace
