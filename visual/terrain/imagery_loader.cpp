#include "terrain/imagery_loader.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <gdal_alg.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>

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

// The box mean overview of a south-first full_w x full_h raster, fed one
// row at a time (south first): ceil(w / step) x ceil(h / step) pixels, each
// the mean of the pixels of its block that exist (rounded to nearest).
class BoxMean {
 public:
  BoxMean(int w, int h, int step)
      : w_(w), h_(h), step_(step), ow_((w + step - 1) / step), sums_(std::size_t(ow_) * 3) {
    out_.resize(std::size_t(ow_) * ((h + step - 1) / step) * 3);
  }
  void add_row(const Rgb8* row) {
    for (int x = 0; x < w_; ++x) {
      std::uint32_t* s = &sums_[std::size_t(x / step_) * 3];
      s[0] += row[x].r, s[1] += row[x].g, s[2] += row[x].b;
    }
    if (++y_ % step_ != 0 && y_ != h_) return;  // the block row is not complete yet
    const int oy = (y_ - 1) / step_, rows = y_ - oy * step_;
    for (int ox = 0; ox < ow_; ++ox) {
      const std::uint32_t n = std::uint32_t(rows) * std::uint32_t(std::min(w_, (ox + 1) * step_) - ox * step_);
      for (int c = 0; c < 3; ++c)
        out_[(std::size_t(oy) * ow_ + ox) * 3 + c] = std::uint8_t((sums_[std::size_t(ox) * 3 + c] + n / 2) / n);
    }
    std::fill(sums_.begin(), sums_.end(), 0u);
  }
  std::vector<std::uint8_t> take() { return std::move(out_); }

 private:
  int w_, h_, step_, ow_, y_ = 0;
  std::vector<std::uint32_t> sums_;
  std::vector<std::uint8_t> out_;
};

// The warped VRT of imagery beyond the limit: rectangles of the footprint
// read on demand (GDAL warps them block by block), as RGB with uncovered
// pixels grey. Not thread-safe (the tile cache calls it on one thread at a
// time). GDAL keeps the blocks it read (the source's and the warp's) in its
// block cache, capped at 256 MB (as for paged heights), so neighbouring
// tiles sharing a block warp it once.
class WarpedImagery {
 public:
  WarpedImagery(Dataset vrt, std::string path) : vrt_(std::move(vrt)), path_(std::move(path)) {
    const int bands = GDALGetRasterCount(handle(vrt_));  // the colour bands, then the destination alpha
    band_map_ = {1, bands >= 3 ? 2 : 1, bands >= 3 ? 3 : 1, bands};  // as the one-texture read_rgb
    height_ = GDALGetRasterYSize(handle(vrt_));
  }
  // Pixels [x0, x0 + w) x [y0, y0 + h), row y0 = south, into out (w * h);
  // returns the uncovered pixels. Throws DemError on a failed read.
  std::int64_t read(int x0, int y0, int w, int h, Rgb8* out) {
    gdal::QuietErrors quiet;
    rgba_.resize(std::size_t(w) * h * 4);
    CPLErrorReset();
    const CPLErr err = GDALDatasetRasterIO(handle(vrt_), GF_Read, x0, height_ - y0 - h, w, h, rgba_.data(), w, h,
                                           GDT_Byte, 4, band_map_.data(), 4, GSpacing(w) * 4, 1);
    if (err != CE_None)
      throw DemError(path_, "imagery read failed at pixels " + std::to_string(x0) + "," + std::to_string(y0) + ": " +
                                last_error("truncated or corrupt file?"));
    std::int64_t uncovered = 0;
    for (int r = 0; r < h; ++r) {  // file row h-1-r is our row r
      const std::uint8_t* in = rgba_.data() + std::size_t(h - 1 - r) * w * 4;
      Rgb8* o = out + std::size_t(r) * w;
      for (int x = 0; x < w; ++x, in += 4)
        if (in[3] == 0) {
          o[x] = {128, 128, 128};
          ++uncovered;
        } else {
          o[x] = {in[0], in[1], in[2]};
        }
    }
    return uncovered;
  }

 private:
  Dataset vrt_;  // opens its own handle on the source
  std::string path_;
  std::array<int, 4> band_map_{};
  int height_ = 0;
  std::vector<std::uint8_t> rgba_;
};

// gdalwarp -of VRT onto the footprint (`args`), its blocks made tile x tile
// (gdalwarp's VRTs have 512 x 128 blocks whatever -co says: the XML is
// rewritten before it is opened).
Dataset warped_vrt(GDALDatasetH src, std::vector<std::string> args, int tile, const std::string& path) {
  static std::atomic<int> serial{0};
  const std::string vsi = "/vsimem/ig_imagery_" + std::to_string(++serial) + ".vrt";
  args.insert(args.end(), {"-of", "VRT"});
  if (!gdal::warp(src, vsi, args)) throw DemError(path, "imagery warp failed: " + last_error("unknown GDAL error"));
  vsi_l_offset n = 0;
  const GByte* bytes = VSIGetMemFileBuffer(vsi.c_str(), &n, FALSE);
  std::string xml = bytes ? std::string(reinterpret_cast<const char*>(bytes), std::size_t(n)) : std::string();
  for (const std::string tag : {"BlockXSize", "BlockYSize"}) {
    const std::size_t a = xml.find("<" + tag + ">"), b = xml.find("</" + tag + ">");
    if (a != std::string::npos && b != std::string::npos && b > a)
      xml.replace(a + tag.size() + 2, b - a - tag.size() - 2, std::to_string(tile));
  }
  VSILFILE* f = VSIFOpenL(vsi.c_str(), "wb");
  const bool written = f && VSIFWriteL(xml.data(), 1, xml.size(), f) == xml.size();
  if (f) VSIFCloseL(f);
  Dataset vrt(written ? GDALOpenEx(vsi.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr) : nullptr);
  VSIUnlink(vsi.c_str());
  if (!vrt) throw DemError(path, "imagery warp failed: " + last_error("the warped VRT does not open"));
  return vrt;
}

}  // namespace

std::size_t imagery_window_budget(int window_side, int tile) {
  // The window and a tile of margin each side, at any alignment.
  const std::size_t n = std::size_t((window_side + 2 * tile + tile - 1) / tile + 1);
  return n * n * std::size_t(tile) * tile * sizeof(Rgb8);
}

Imagery load_imagery(const Heightfield& hf, const std::string& path, int max_side, const ImageryPaging& paging) {
  // File-system checks first, so the common mistakes read plainly (GDAL's
  // virtual paths, /vsicurl/ ..., are left to GDAL).
  if (path.rfind("/vsi", 0) != 0) {
    std::error_code fs_error;
    const auto st = std::filesystem::status(path, fs_error);
    if (path.empty() || st.type() == std::filesystem::file_type::not_found) throw DemError(path, "no such file");
    if (fs_error) throw DemError(path, "cannot access: " + fs_error.message());
    if (st.type() == std::filesystem::file_type::directory) throw DemError(path, "is a folder, not an image");
  }
  gdal::register_once();
  gdal::QuietErrors quiet;
  // A relative file opened by its absolute path: the paged path's warped VRT
  // (in /vsimem/) names its source by it.
  std::error_code ec;
  const std::string open_path = std::filesystem::path(path).is_relative() && std::filesystem::is_regular_file(path, ec)
                                    ? std::filesystem::absolute(path, ec).string()
                                    : path;
  Dataset src(GDALOpenEx(open_path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
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
    if (want_x <= max_side && want_y <= max_side) {  // fits one texture
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
    std::vector<std::string> args = {"-t_srs", hf.georef->crs_wkt, "-te", number_arg(b[0]), number_arg(b[1]),
                                     number_arg(b[2]), number_arg(b[3]), "-ts", std::to_string(out.full_width()),
                                     std::to_string(out.full_height()), "-r", "bilinear", "-dstalpha"};
    out.warped = true;
    if (out.full_step > 1) {
      // Paged: a warped VRT read tile by tile (blocks of one tile, so a tile
      // is warped once), the overview and the uncovered count in one pass.
      const int tile = std::max(paging.tile, 16);
      if (GDALGetCacheMax64() > (GIntBig(256) << 20)) GDALSetCacheMax64(GIntBig(256) << 20);
      auto warped = std::make_shared<WarpedImagery>(warped_vrt(h, args, tile, path), path);
      src.reset();
      const int fw = out.full_w, fh = out.full_h;
      BoxMean overview(fw, fh, out.full_step);
      std::vector<Rgb8> strip(std::size_t(fw) * tile);
      for (int y0 = 0; y0 < fh; y0 += tile) {
        const int rows = std::min(tile, fh - y0);
        out.uncovered += warped->read(0, y0, fw, rows, strip.data());
        for (int r = 0; r < rows; ++r) overview.add_row(strip.data() + std::size_t(r) * fw);
      }
      out.rgb = overview.take();
      auto paged = std::make_shared<PagedImagery>();
      auto failed = paged->failed_tiles;
      const std::size_t budget = std::max(paging.budget_bytes, imagery_window_budget(paging.window_side, tile));
      paged->cache = std::make_shared<const RgbTileCache>(
          fw, fh, tile, budget, [warped, failed, path](int tx, int ty, int x0, int y0, int w, int ht, Rgb8* o) {
            try {
              warped->read(x0, y0, w, ht, o);
            } catch (const std::exception& e) {  // drawn grey, counted, logged; never thrown at a frame
              std::fill(o, o + std::size_t(w) * ht, Rgb8{128, 128, 128});
              if (++*failed <= 5)
                std::fprintf(stderr, "ig: imagery tile %d,%d unreadable, drawn grey: %s\n", tx, ty, e.what());
            }
          });
      out.paged = std::move(paged);
      return out;
    }
    for (const char* a : {"-of", "MEM"}) args.emplace_back(a);
    use = gdal::warp(h, "", args);
    if (!use) throw DemError(path, "imagery warp failed: " + last_error("unknown GDAL error"));
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
  out.rgb = std::move(rgb);
  return out;
}

}  // namespace ig::terrain
