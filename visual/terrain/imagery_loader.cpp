#include "terrain/imagery_loader.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal.h>
#include <gdal_alg.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "terrain/dem_loader.h"
#include "terrain/gdal_support.h"

namespace ig::terrain {
namespace {

using gdal::Dataset;
using gdal::handle;
using gdal::last_error;
using gdal::number_arg;

// Reads bands 1-3 (or band 1 three times for grey) as RGB, north row first.
std::vector<std::uint8_t> read_rgb(GDALDatasetH ds, const std::string& path) {
  const int w = GDALGetRasterXSize(ds), h = GDALGetRasterYSize(ds), bands = GDALGetRasterCount(ds);
  if (bands < 1) throw DemError(path, "imagery has no raster bands");
  std::vector<std::uint8_t> rgb(std::size_t(w) * h * 3);
  for (int c = 0; c < 3; ++c) {
    GDALRasterBandH band = GDALGetRasterBand(ds, bands >= 3 ? c + 1 : 1);
    if (GDALRasterIO(band, GF_Read, 0, 0, w, h, rgb.data() + c, w, h, GDT_Byte, 3, GSpacing(w) * 3) != CE_None)
      throw DemError(path, "imagery read failed: " + last_error("truncated or corrupt file?"));
  }
  return rgb;
}

// Box-averages a south-first w x h RGB raster by `step`: ceil(w / step) x
// ceil(h / step) pixels, each the mean of the pixels of its block that exist.
std::vector<std::uint8_t> box_average(const std::vector<std::uint8_t>& rgb, int w, int h, int step) {
  const int ow = (w + step - 1) / step, oh = (h + step - 1) / step;
  std::vector<std::uint8_t> out(std::size_t(ow) * oh * 3);
  std::vector<std::uint32_t> sums(std::size_t(ow) * 3);
  for (int oy = 0; oy < oh; ++oy) {
    std::fill(sums.begin(), sums.end(), 0u);
    const int y1 = std::min(h, (oy + 1) * step);
    for (int y = oy * step; y < y1; ++y) {
      const std::uint8_t* row = rgb.data() + std::size_t(y) * w * 3;
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c) sums[std::size_t(x / step) * 3 + c] += row[std::size_t(x) * 3 + c];
    }
    for (int ox = 0; ox < ow; ++ox) {
      const std::uint32_t n = std::uint32_t(y1 - oy * step) * std::uint32_t(std::min(w, (ox + 1) * step) - ox * step);
      for (int c = 0; c < 3; ++c)
        out[(std::size_t(oy) * ow + ox) * 3 + c] = std::uint8_t((sums[std::size_t(ox) * 3 + c] + n / 2) / n);
    }
  }
  return out;
}

}  // namespace

Imagery load_imagery(const Heightfield& hf, const std::string& path, int max_side) {
  gdal::register_once();
  gdal::QuietErrors quiet;
  Dataset src(GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  if (!src) throw DemError(path, "imagery cannot be read: " + last_error("not a recognised raster format"));
  GDALDatasetH h = handle(src);
  double gt[6];
  const bool georeferenced = GDALGetGeoTransform(h, gt) == CE_None && GDALGetSpatialRef(h) != nullptr;

  Imagery out;
  Dataset use;  // what is read: the source, or its warp onto the DEM's footprint
  if (georeferenced && hf.georef && !hf.georef->crs_wkt.empty()) {
    const auto b = *hf.crs_bounds();  // the DEM's footprint: west, south, east, north
    // The image's own resolution over the DEM, capped: about its pixel size
    // in the DEM's CRS (GDAL's suggestion), at least the DEM's sample grid.
    double suggested[6];
    int sw = 0, sh = 0;
    void* transform = GDALCreateGenImgProjTransformer(h, nullptr, nullptr, hf.georef->crs_wkt.c_str(), FALSE, 0, 1);
    if (!transform) throw DemError(path, "imagery CRS cannot be transformed to the DEM's: " + last_error("no transformation"));
    const CPLErr err = GDALSuggestedWarpOutput(h, GDALGenImgProjTransform, transform, suggested, &sw, &sh);
    GDALDestroyGenImgProjTransformer(transform);
    if (err != CE_None) throw DemError(path, "imagery cannot be placed on the DEM: " + last_error("warp failed"));
    const double sx = suggested[0], sx1 = suggested[0] + sw * suggested[1];
    const double sy = suggested[3] + sh * suggested[5], sy1 = suggested[3];
    if (sx1 <= b[0] || sx >= b[2] || sy1 <= b[1] || sy >= b[3])
      throw DemError(path, "imagery does not overlap the DEM (imagery " + number_arg(sx) + ".." + number_arg(sx1) + " x " + number_arg(sy) +
                               ".." + number_arg(sy1) + ", DEM " + number_arg(b[0]) + ".." + number_arg(b[2]) + " x " + number_arg(b[1]) + ".." +
                               number_arg(b[3]) + " in the DEM's CRS)");
    const double per_x = (b[2] - b[0]) / std::abs(suggested[1]), per_y = (b[3] - b[1]) / std::abs(suggested[5]);
    double want_x = std::max(double(std::lround(per_x)), double(hf.width));
    double want_y = std::max(double(std::lround(per_y)), double(hf.height));
    const double shrink = std::sqrt(double(kMaxFullImageryBytes) / (3.0 * want_x * want_y));
    if (shrink < 1.0) want_x *= shrink, want_y *= shrink;  // held in memory: capped
    if (want_x <= max_side && want_y <= max_side) {  // one texture, as before issue 16's window
      out.width = int(want_x);
      out.height = int(want_y);
    } else {
      // Full resolution as wanted (not rounded: that would resample every
      // pixel); the overview's step the smallest that fits the limit.
      out.full_w = int(want_x);
      out.full_h = int(want_y);
      out.full_step = (std::max(out.full_w, out.full_h) + max_side - 1) / max_side;
      out.width = (out.full_w + out.full_step - 1) / out.full_step;
      out.height = (out.full_h + out.full_step - 1) / out.full_step;
    }
    use = gdal::warp(h, "", {"-of", "MEM", "-t_srs", hf.georef->crs_wkt, "-te", number_arg(b[0]), number_arg(b[1]),
                             number_arg(b[2]), number_arg(b[3]), "-ts", std::to_string(out.full_width()),
                             std::to_string(out.full_height()), "-r", "bilinear", "-dstalpha"});
    if (!use) throw DemError(path, "imagery warp failed: " + last_error("unknown GDAL error"));
    out.warped = true;
  } else {
    out.width = GDALGetRasterXSize(h);
    out.height = GDALGetRasterYSize(h);
    if (out.width > max_side || out.height > max_side)
      throw DemError(path, "imagery " + std::to_string(out.width) + "x" + std::to_string(out.height) +
                               " without georeferencing exceeds the texture limit " + std::to_string(max_side) +
                               " (give it georeferencing and it is resampled)");
  }
  GDALDatasetH ds = handle(use ? use : src);
  auto rgb = read_rgb(ds, path);
  const int fw = out.full_width(), fh = out.full_height();
  if (out.warped) {  // the destination alpha band says where the image covers the footprint
    const int bands = GDALGetRasterCount(ds);
    std::vector<std::uint8_t> alpha(std::size_t(fw) * fh);
    if (GDALRasterIO(GDALGetRasterBand(ds, bands), GF_Read, 0, 0, fw, fh, alpha.data(), fw, fh, GDT_Byte, 0, 0) !=
        CE_None)
      throw DemError(path, "imagery coverage read failed: " + last_error("unknown GDAL error"));
    for (std::size_t p = 0; p < alpha.size(); ++p)
      if (alpha[p] == 0) {
        ++out.uncovered;
        rgb[3 * p] = rgb[3 * p + 1] = rgb[3 * p + 2] = 128;
      }
  }
  use.reset();  // the warp's copy is no longer needed
  // North row first in the raster; south first in the DEM's texture (in
  // place: no second copy of a large image).
  const std::size_t row = std::size_t(fw) * 3;
  for (int y = 0; y < fh / 2; ++y)
    std::swap_ranges(rgb.begin() + std::ptrdiff_t(y * row), rgb.begin() + std::ptrdiff_t((y + 1) * row),
                     rgb.begin() + std::ptrdiff_t((fh - 1 - y) * row));
  if (out.full_step == 1) {
    out.rgb = std::move(rgb);
  } else {
    out.rgb = box_average(rgb, fw, fh, out.full_step);
    out.full_rgb = std::move(rgb);
  }
  return out;
}

}  // namespace ig::terrain
