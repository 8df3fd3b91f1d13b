// Image-space error metrics (visual/stats/image_error.*) on synthetic
// buffers whose answers are known by construction. No GL.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "render/camera.h"
#include "stats/image_error.h"

namespace {

using ig::render::Camera;
using ig::stats::FrameImage;
using ig::stats::image_error;

// Reversed-Z depth of a view distance d for `cam` (inverse of Camera::depth_to_view_distance).
float depth_of(const Camera& cam, double d) {
  return float(cam.near_m * (cam.far_m - d) / (d * (cam.far_m - cam.near_m)));
}

// All sky: depth 0, colour (50, 100, 200).
FrameImage sky(int w, int h) {
  FrameImage f;
  f.width = w;
  f.height = h;
  f.depth.assign(std::size_t(w) * h, 0.0f);
  f.rgba.resize(std::size_t(w) * h * 4);
  for (std::size_t p = 0; p < f.depth.size(); ++p) {
    f.rgba[4 * p] = 50;
    f.rgba[4 * p + 1] = 100;
    f.rgba[4 * p + 2] = 200;
    f.rgba[4 * p + 3] = 255;
  }
  return f;
}

// Terrain at view distance d from row `top` down in columns [x0, x1).
void fill_terrain(FrameImage& f, const Camera& cam, int x0, int x1, int top, double d = 1000.0) {
  for (int y = top; y < f.height; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::size_t p = std::size_t(y) * f.width + x;
      f.depth[p] = depth_of(cam, d);
      f.rgba[4 * p] = 90;
      f.rgba[4 * p + 1] = 80;
      f.rgba[4 * p + 2] = 60;
    }
}

TEST(ImageError, IdenticalFramesHaveNoErrorAndAFinitePsnr) {
  Camera cam;
  FrameImage ref = sky(40, 30);
  fill_terrain(ref, cam, 0, 40, 12);
  const auto e = image_error(ref, ref, cam);
  EXPECT_EQ(e.horizon_columns, 40);
  EXPECT_EQ(e.horizon_one_sided_columns, 0);
  EXPECT_EQ(e.horizon_mean_px, 0.0);
  EXPECT_EQ(e.horizon_max_px, 0.0);
  EXPECT_EQ(e.depth_pixels, 40 * 18);
  EXPECT_EQ(e.depth_rel_p95, 0.0);
  EXPECT_EQ(e.depth_rel_max, 0.0);
  EXPECT_EQ(e.holes, 0);
  EXPECT_EQ(e.reference_terrain_pixels, 40 * 18);
  EXPECT_EQ(e.mse, 0.0);
  // Capped at one one-level difference among 40*30*3 channel values.
  EXPECT_NEAR(e.psnr_db, 10.0 * std::log10(255.0 * 255.0 * 40 * 30 * 3), 1e-9);
  EXPECT_TRUE(std::isfinite(e.psnr_db));
}

TEST(ImageError, HorizonOffsetAndHolesOfALoweredHalf) {
  Camera cam;
  constexpr int w = 20, h = 30;
  FrameImage ref = sky(w, h), m = sky(w, h);
  fill_terrain(ref, cam, 0, w, 10);
  fill_terrain(m, cam, 0, w / 2, 13);  // left half 3 rows lower
  fill_terrain(m, cam, w / 2, w, 10);
  ig::stats::ImageErrorOptions o;
  o.list_interior_holes = true;
  const auto e = image_error(m, ref, cam, o);
  EXPECT_EQ(e.horizon_columns, w);
  EXPECT_DOUBLE_EQ(e.horizon_mean_px, 3.0 * (w / 2) / w);
  EXPECT_DOUBLE_EQ(e.horizon_max_px, 3.0);
  EXPECT_EQ(e.holes, 3 * (w / 2));
  // Rows 10 and 11 lie within 2 rows of the reference sky (row 9): silhouette
  // pixels. Row 12 is interior.
  EXPECT_EQ(e.interior_holes, w / 2);
  ASSERT_EQ(e.interior_hole_pixels.size(), std::size_t(w / 2));
  for (std::size_t p : e.interior_hole_pixels) {
    EXPECT_EQ(int(p) / w, 12);
    EXPECT_LT(int(p) % w, w / 2);
  }
  // Interior pixels: rows 12..29 everywhere, row 11 has sky 2 rows up: 18 rows.
  EXPECT_EQ(e.interior_pixels, (long long)w * 18);
  EXPECT_EQ(e.enclosed_holes, 0) << "a lowered silhouette uncovers sky above it, not through the surface";
  EXPECT_EQ(e.extra_terrain_pixels, 0);
  EXPECT_EQ(e.depth_pixels, (long long)w * (h - 10) - 3 * (w / 2));
  EXPECT_NEAR(e.depth_rel_max, 0.0, 1e-6);
}

TEST(ImageError, CracksAreEnclosedHoles) {
  Camera cam;
  constexpr int w = 16, h = 12;
  FrameImage ref = sky(w, h), m = sky(w, h);
  fill_terrain(ref, cam, 0, w, 4);
  fill_terrain(m, cam, 0, w, 4);
  // A crack: one column of sky from row 7 to row 9 below intact terrain.
  for (int y = 7; y <= 9; ++y) m.depth[std::size_t(y) * w + 5] = 0.0f;
  // And a silhouette lowered by 2 rows in column 10.
  m.depth[std::size_t(4) * w + 10] = m.depth[std::size_t(5) * w + 10] = 0.0f;
  const auto e = image_error(m, ref, cam);
  EXPECT_EQ(e.holes, 5);
  EXPECT_EQ(e.enclosed_holes, 3);
  EXPECT_EQ(e.interior_holes, 3);  // rows 7..9 are more than 2 rows below the reference sky
  EXPECT_DOUBLE_EQ(e.horizon_max_px, 2.0);
}

TEST(ImageError, ColumnsWithTerrainInOneImageCountToTheBottomEdge) {
  Camera cam;
  constexpr int w = 8, h = 6;
  FrameImage ref = sky(w, h), m = sky(w, h);
  fill_terrain(ref, cam, 0, 4, 3);  // columns 4..7: sky in both, left out
  fill_terrain(m, cam, 0, 3, 4);    // column 3: no terrain in the method image
  fill_terrain(m, cam, 7, 8, 5);    // column 7: terrain only in the method image
  const auto e = image_error(m, ref, cam);
  EXPECT_EQ(e.horizon_columns, 5);
  EXPECT_EQ(e.horizon_one_sided_columns, 2);
  // Offsets: 1, 1, 1, (6 - 3) = 3 and (6 - 5) = 1.
  EXPECT_DOUBLE_EQ(e.horizon_mean_px, 7.0 / 5.0);
  EXPECT_DOUBLE_EQ(e.horizon_max_px, 3.0);
  EXPECT_EQ(e.extra_terrain_pixels, 1);
}

TEST(ImageError, AllSkyInBothHasNoHorizonColumns) {
  Camera cam;
  const FrameImage a = sky(16, 8);
  const auto e = image_error(a, a, cam);
  EXPECT_EQ(e.horizon_columns, 0);
  EXPECT_EQ(e.horizon_mean_px, 0.0);
  EXPECT_EQ(e.depth_pixels, 0);
  EXPECT_EQ(e.depth_rel_p95, 0.0);
  EXPECT_EQ(e.reference_terrain_pixels, 0);
}

TEST(ImageError, DepthPercentileIsNearestRankOverTerrainInBoth) {
  Camera cam;
  constexpr int w = 10, h = 10;
  FrameImage ref = sky(w, h), m = sky(w, h);
  fill_terrain(ref, cam, 0, w, 0, 1000.0);
  fill_terrain(m, cam, 0, w, 0, 1000.0);
  // 100 pixels: 89 exact, 10 at +10 %, one at +50 %.
  for (int p = 0; p < 10; ++p) m.depth[p] = depth_of(cam, 1100.0);
  m.depth[10] = depth_of(cam, 1500.0);
  const auto e = image_error(m, ref, cam);
  EXPECT_EQ(e.depth_pixels, 100);
  EXPECT_NEAR(e.depth_rel_p95, 0.1, 1e-4);  // the 95th of 100 sorted values
  EXPECT_NEAR(e.depth_rel_max, 0.5, 1e-4);
  // Further errors below the 95th value do not move it; a hole leaves the depth set.
  m.depth[99] = 0.0f;
  const auto e2 = image_error(m, ref, cam);
  EXPECT_EQ(e2.depth_pixels, 99);
  EXPECT_EQ(e2.holes, 1);
  EXPECT_NEAR(e2.depth_rel_p95, 0.1, 1e-4);
  // Depth is relative to the reference distance, in either direction.
  for (int p = 0; p < 100; ++p) m.depth[p] = depth_of(cam, 800.0);
  EXPECT_NEAR(image_error(m, ref, cam).depth_rel_max, 0.2, 1e-4);
}

TEST(ImageError, PsnrUsesRgbOnly) {
  Camera cam;
  constexpr int w = 12, h = 9;
  FrameImage ref = sky(w, h), m = sky(w, h);
  for (std::size_t p = 0; p < std::size_t(w) * h; ++p) {
    m.rgba[4 * p + 1] = std::uint8_t(m.rgba[4 * p + 1] + 10);  // green off by 10
    m.rgba[4 * p + 3] = 0;                                      // alpha carries method data
  }
  const auto e = image_error(m, ref, cam);
  EXPECT_NEAR(e.mse, 100.0 / 3.0, 1e-12);
  EXPECT_NEAR(e.psnr_db, 10.0 * std::log10(255.0 * 255.0 * 3.0 / 100.0), 1e-9);
}

TEST(ImageError, NanDepthIsCountedAndTreatedAsSky) {
  Camera cam;
  FrameImage ref = sky(6, 6), m = sky(6, 6);
  fill_terrain(ref, cam, 0, 6, 0);
  fill_terrain(m, cam, 0, 6, 0);
  m.depth[20] = std::numeric_limits<float>::quiet_NaN();
  const auto e = image_error(m, ref, cam);
  EXPECT_EQ(e.invalid_depth_pixels, 1);
  EXPECT_EQ(e.holes, 1);
  EXPECT_EQ(e.depth_pixels, 35);
  EXPECT_TRUE(std::isfinite(e.depth_rel_max));
}

TEST(ImageError, MismatchedOrMalformedBuffersThrow) {
  Camera cam;
  const FrameImage a = sky(8, 6), b = sky(6, 8);
  EXPECT_THROW(image_error(a, b, cam), std::invalid_argument);
  FrameImage c = sky(8, 6);
  c.depth.pop_back();
  EXPECT_THROW(image_error(c, a, cam), std::invalid_argument);
  FrameImage empty;
  EXPECT_THROW(image_error(empty, empty, cam), std::invalid_argument);
}

TEST(ImageError, PsnrFromMseIsMonotonicAndFloored) {
  const double n = 300.0;
  EXPECT_GT(ig::stats::psnr_db_from_mse(1.0, n), ig::stats::psnr_db_from_mse(2.0, n));
  EXPECT_DOUBLE_EQ(ig::stats::psnr_db_from_mse(0.0, n), ig::stats::psnr_db_from_mse(1.0 / n, n));
  EXPECT_NEAR(ig::stats::psnr_db_from_mse(255.0 * 255.0, n), 0.0, 1e-12);
}

}  // namespace
