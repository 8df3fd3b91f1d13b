// Imagery draped over a DEM (terrain/imagery_loader.h): georeferenced images
// of another extent, resolution or CRS land on the DEM's samples; images
// without georeferencing span the DEM; non-overlapping ones are refused.
#include <gtest/gtest.h>

#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "terrain/dem_loader.h"
#include "terrain/imagery_loader.h"
#include "imagery_test_data.h"

namespace {

namespace fs = std::filesystem;
using imagery_test::colour_of;
using imagery_test::dem;
using imagery_test::kRes;
using imagery_test::write_image;

// Every DEM sample's imagery texel has the colour of the sample's place.
void expect_on_samples(const ig::terrain::Heightfield& hf, const ig::terrain::Imagery& img, double tolerance) {
  ASSERT_EQ(img.rgb.size(), std::size_t(img.width) * img.height * 3);
  double worst = 0.0;
  for (int j = 2; j < hf.height - 2; j += 3)
    for (int i = 2; i < hf.width - 2; i += 3) {
      // The texel the shader reads for sample (i, j): (s + 0.5) / dem_size.
      const int x = int((i + 0.5) / hf.width * img.width), y = int((j + 0.5) / hf.height * img.height);
      const auto& g = hf.georef->grid_to_crs;
      const auto want = colour_of(g[0] + i * g[1], g[3] + j * g[5]);
      const std::uint8_t* px = &img.rgb[(std::size_t(y) * img.width + x) * 3];
      worst = std::max({worst, std::abs(px[0] - want[0]), std::abs(px[1] - want[1])});
    }
  EXPECT_LE(worst, tolerance);
}

TEST(ImageryLoader, GeographicImageOfALargerExtentAndFinerResolutionLandsOnTheSamples) {
  const auto hf = dem(61, 49);
  // 3x finer, starting 0.01 degree west and north of the DEM.
  const double gt[6] = {-118.0 - 0.5 * kRes - 0.01, kRes / 3, 0, 37.0 + 0.5 * kRes + 0.01, 0, -kRes / 3};
  const auto path = write_image("ig_imagery_geo.tif", 4326, gt, 400, 400);
  const auto img = ig::terrain::load_imagery(hf, path, 16384);
  EXPECT_TRUE(img.warped);
  EXPECT_EQ(img.uncovered, 0);
  EXPECT_GE(img.width, 3 * 61 - 3);
  expect_on_samples(hf, img, 3.0);
  fs::remove(path);
}

// All full-resolution pixels of paged imagery, as one south-first RGB array.
std::vector<std::uint8_t> all_pixels(const ig::terrain::Imagery& img) {
  const int fw = img.full_width(), fh = img.full_height();
  std::vector<ig::terrain::Rgb8> px(std::size_t(fw) * fh);
  img.paged->cache->read_rect(0, 0, fw, fh, px.data(), fw);
  std::vector<std::uint8_t> rgb(px.size() * 3);
  for (std::size_t p = 0; p < px.size(); ++p) rgb[3 * p] = px[p].r, rgb[3 * p + 1] = px[p].g, rgb[3 * p + 2] = px[p].b;
  return rgb;
}

// A budget small enough that reading everything evicts: tiles of 16 pixels
// for a window of 8 (the least the window needs is 4 x 4 tiles).
ig::terrain::ImageryPaging tiny_paging() {
  ig::terrain::ImageryPaging p;
  p.budget_bytes = 1;
  p.tile = 16;
  p.window_side = 8;
  return p;
}

// The overview is the step x step box mean of the full resolution (fewer
// pixels in the last row and column).
void expect_box_mean_overview(const ig::terrain::Imagery& img, const std::vector<std::uint8_t>& full) {
  const int f = img.full_step, fw = img.full_width(), fh = img.full_height();
  EXPECT_EQ(img.width, (fw + f - 1) / f);
  EXPECT_EQ(img.height, (fh + f - 1) / f);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) {
        int sum = 0, n = 0;
        for (int v = y * f; v < std::min(fh, (y + 1) * f); ++v)
          for (int u = x * f; u < std::min(fw, (x + 1) * f); ++u, ++n) sum += full[(std::size_t(v) * fw + u) * 3 + c];
        ASSERT_EQ(img.rgb[(std::size_t(y) * img.width + x) * 3 + c], (sum + n / 2) / n) << x << "," << y;
      }
}

// Beyond the texture limit: the full resolution is paged from a
// warped VRT and every pixel equals the one-texture (in-memory) warp's, with
// a budget that forces evictions; the overview is its step x step box mean.
TEST(ImageryLoader, ImageBeyondTheLimitIsPagedWithTheInMemoryPixelsAndABoxMeanOverview) {
  const auto hf = dem(61, 49);
  const double gt[6] = {-118.0 - 0.5 * kRes - 0.01, kRes / 3, 0, 37.0 + 0.5 * kRes + 0.01, 0, -kRes / 3};
  const auto path = write_image("ig_imagery_beyond.tif", 4326, gt, 400, 400);
  const auto whole = ig::terrain::load_imagery(hf, path, 16384);
  const auto img = ig::terrain::load_imagery(hf, path, 50, tiny_paging());  // step 4: 183 = 45 * 4 + 3, a partial block
  EXPECT_FALSE(whole.paged);
  EXPECT_EQ(whole.full_step, 1);
  ASSERT_GT(img.full_step, 1);
  ASSERT_TRUE(img.paged);
  EXPECT_LE(img.width, 50);
  EXPECT_LE(img.height, 50);
  EXPECT_EQ(img.full_width(), whole.width);
  EXPECT_EQ(img.full_height(), whole.height);
  EXPECT_NE(img.full_width() % img.full_step, 0);  // the last column is a partial block
  const auto full = all_pixels(img);
  EXPECT_EQ(full, whole.rgb);
  expect_box_mean_overview(img, full);
  const auto& cache = *img.paged->cache;
  EXPECT_EQ(cache.budget_bytes(), ig::terrain::imagery_window_budget(8, 16));  // raised to the window's need
  EXPECT_LE(cache.stats().peak_resident_bytes, cache.budget_bytes());
  EXPECT_GT(cache.stats().evictions, 0);
  EXPECT_EQ(*img.paged->failed_tiles, 0);
  fs::remove(path);
}

// Imagery over part of the footprint: the same pixels grey (128) and the
// same uncovered count, paged or in memory; a projected image reprojected
// tile by tile equals the one-pass warp within one step on a few values.
TEST(ImageryLoader, PagedImageryCountsUncoveredPixelsAndReprojectsLikeTheInMemoryWarp) {
  const auto hf = dem(61, 49);
  const double west_half[6] = {-118.0 - 0.5 * kRes, kRes / 3, 0, 37.0 + 0.5 * kRes, 0, -kRes / 3};
  const double utm[6] = {409500.0, 30.0, 0.0, 4096500.0, 0.0, -30.0};
  for (const auto& [name, epsg, gt, w, h] :
       {std::tuple{"ig_imagery_half.tif", 4326, west_half, 90, 147}, std::tuple{"ig_imagery_utm_paged.tif", 32611, utm, 300, 300}}) {
    SCOPED_TRACE(name);
    const auto path = write_image(name, epsg, gt, w, h, /*tiled=*/true);
    const auto whole = ig::terrain::load_imagery(hf, path, 16384);
    const int side = std::max(whole.width, whole.height);
    const auto img = ig::terrain::load_imagery(hf, path, side / 2, tiny_paging());
    ASSERT_TRUE(img.paged);
    EXPECT_EQ(img.uncovered, whole.uncovered);
    if (epsg == 4326) {
      EXPECT_GT(img.uncovered, 0);
    }
    const auto full = all_pixels(img);
    ASSERT_EQ(full.size(), whole.rgb.size());
    std::size_t differ = 0;
    int worst = 0;
    for (std::size_t k = 0; k < full.size(); ++k) {
      differ += full[k] != whole.rgb[k];
      worst = std::max(worst, std::abs(int(full[k]) - int(whole.rgb[k])));
    }
    if (epsg == 4326) {
      EXPECT_EQ(differ, 0u) << "largest difference " << worst;  // same CRS: an exact (affine) transform
    } else {
      // Reprojected: GDAL's approximate transformer (error 0.125 pixel)
      // interpolates along each warp chunk's rows, and the chunks differ
      // (VRT blocks of one tile, 16 here, vs one in-memory pass): a few
      // 1-step changes (102 of 66234 values when written).
      EXPECT_LE(worst, 1);
      EXPECT_LE(differ, full.size() / 100) << differ << " of " << full.size();
    }
    expect_box_mean_overview(img, full);
    fs::remove(path);
  }
}

// A relative path (from the working directory) works paged too: the
// warped VRT kept in /vsimem/ names its source by its absolute path.
TEST(ImageryLoader, PagedImageryByARelativePathReadsTheFile) {
  const auto hf = dem(61, 49);
  const double gt[6] = {-118.0 - 0.5 * kRes - 0.01, kRes / 3, 0, 37.0 + 0.5 * kRes + 0.01, 0, -kRes / 3};
  const auto path = write_image("ig_imagery_relative.tif", 4326, gt, 400, 400, /*tiled=*/true);
  const auto whole = ig::terrain::load_imagery(hf, path, 16384);
  const fs::path cwd = fs::current_path();
  fs::current_path(fs::path(path).parent_path());
  ig::terrain::Imagery img;
  EXPECT_NO_THROW(img = ig::terrain::load_imagery(hf, "ig_imagery_relative.tif", 50, tiny_paging()));
  fs::current_path(cwd);
  ASSERT_TRUE(img.paged);
  EXPECT_EQ(all_pixels(img), whole.rgb);
  fs::remove(path);
}

// The file going bad after the load (truncated under a running IG): the
// tiles that cannot be read are drawn grey and counted, nothing throws.
TEST(ImageryLoader, TilesUnreadableAfterTheLoadAreGreyAndCounted) {
  const auto hf = dem(61, 49);
  const double gt[6] = {-118.0 - 0.5 * kRes - 0.01, kRes / 3, 0, 37.0 + 0.5 * kRes + 0.01, 0, -kRes / 3};
  const auto path = write_image("ig_imagery_truncated.tif", 4326, gt, 400, 400, /*tiled=*/true);
  const auto img = ig::terrain::load_imagery(hf, path, 50, tiny_paging());
  ASSERT_TRUE(img.paged);
  fs::resize_file(path, fs::file_size(path) / 3);
  // GDAL's block cache emptied (as it is for an image far larger than it),
  // so the tiles' reads reach the file.
  const GIntBig cache_max = GDALGetCacheMax64();
  GDALSetCacheMax64(0);
  std::vector<std::uint8_t> full;
  EXPECT_NO_THROW(full = all_pixels(img));
  GDALSetCacheMax64(cache_max);
  EXPECT_GT(*img.paged->failed_tiles, 0);
  const auto& cache = *img.paged->cache;
  // Some tile is all grey.
  bool grey_tile = false;
  for (int ty = 0; ty < cache.tiles_y() && !grey_tile; ++ty)
    for (int tx = 0; tx < cache.tiles_x() && !grey_tile; ++tx) {
      bool all = true;
      for (int v = ty * 16; v < std::min((ty + 1) * 16, img.full_height()) && all; ++v)
        for (int u = tx * 16; u < std::min((tx + 1) * 16, img.full_width()) && all; ++u)
          for (int c = 0; c < 3; ++c) all = all && full[(std::size_t(v) * img.full_width() + u) * 3 + c] == 128;
      grey_tile = all;
    }
  EXPECT_TRUE(grey_tile);
  fs::remove(path);
}

TEST(ImageryLoader, UtmImageIsReprojectedOntoTheDem) {
  const auto hf = dem(61, 49);
  // UTM 11N around (-118 + 0.025, 37 - 0.02): easting ~ 411 km, northing ~ 4092 km; 30 m pixels.
  const double gt[6] = {409500.0, 30.0, 0.0, 4096500.0, 0.0, -30.0};
  const auto path = write_image("ig_imagery_utm.tif", 32611, gt, 300, 300);
  const auto img = ig::terrain::load_imagery(hf, path, 16384);
  EXPECT_TRUE(img.warped);
  expect_on_samples(hf, img, 4.0);
  fs::remove(path);
}

TEST(ImageryLoader, ImageElsewhereIsRefusedAndPlainImagesSpanTheDem) {
  const auto hf = dem(61, 49);
  const double far_away[6] = {10.0, kRes, 0, 50.0, 0, -kRes};
  const auto path = write_image("ig_imagery_far.tif", 4326, far_away, 50, 50);
  try {
    ig::terrain::load_imagery(hf, path, 16384);
    ADD_FAILURE() << "imagery far from the DEM was accepted";
  } catch (const ig::terrain::DemError& e) {
    EXPECT_NE(std::string(e.what()).find("does not overlap the DEM"), std::string::npos) << e.what();
  }
  fs::remove(path);
  // No georeferencing: taken as spanning the DEM, rows flipped south first.
  const std::string plain = (fs::temp_directory_path() / "ig_imagery_plain.tif").string();
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), plain.c_str(), 4, 3, 1, GDT_Byte, nullptr);
  std::vector<std::uint8_t> grey = {0, 0, 0, 0, 50, 50, 50, 50, 200, 200, 200, 200};  // north row first
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, 4, 3, grey.data(), 4, 3, GDT_Byte, 0, 0), CE_None);
  GDALClose(ds);
  const auto img = ig::terrain::load_imagery(hf, plain, 16384);
  EXPECT_FALSE(img.warped);
  EXPECT_EQ(img.width, 4);
  EXPECT_EQ(img.rgb[0], 200);                  // south row first
  EXPECT_EQ(img.rgb[(2 * 4) * 3 + 1], 0);      // north row last, grey in every channel
  fs::remove(plain);
  EXPECT_THROW(ig::terrain::load_imagery(hf, "/nonexistent/x.tif", 16384), ig::terrain::DemError);
}

// The common mistakes read plainly, naming the file.
TEST(ImageryLoader, AMissingFileOrAFolderSaysSo) {
  const auto hf = dem(61, 49);
  auto message = [&](const std::string& path) {
    try {
      ig::terrain::load_imagery(hf, path, 16384);
    } catch (const ig::terrain::DemError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("/nonexistent/ortho.png"), "/nonexistent/ortho.png: no such file");
  const std::string folder = fs::temp_directory_path().string();
  EXPECT_EQ(message(folder), folder + ": is a folder, not an image");
}

}  // namespace
