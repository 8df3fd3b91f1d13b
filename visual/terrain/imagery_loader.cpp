#include "terrain/imagery_loader.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal.h>
#include <gdal_alg.h>
#include <gdal_utils.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>

#include "terrain/dem_loader.h"

namespace ig::terrain {
namespace {

struct DatasetCloser {
  void operator()(void* ds) const {
    if (ds) GDALClose(static_cast<GDALDatasetH>(ds));
  }
};
using Dataset = std::unique_ptr<void, DatasetCloser>;

struct QuietGdal {
  QuietGdal() {
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
  }
  ~QuietGdal() { CPLPopErrorHandler(); }
};

std::string last_error(const char* otherwise) {
  std::string m = CPLGetLastErrorMsg();
  std::replace(m.begin(), m.end(), '\n', ' ');
  return m.empty() ? std::string(otherwise) : m;
}

std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// The DEM's footprint in its CRS: outer sample edges (west, south, east, north).
std::array<double, 4> dem_bounds(const Heightfield& hf) {
  const auto& g = hf.georef->grid_to_crs;
  double w = 1e300, s = 1e300, e = -1e300, n = -1e300;
  for (double i : {-0.5, hf.width - 0.5})
    for (double j : {-0.5, hf.height - 0.5}) {
      const double x = g[0] + i * g[1] + j * g[2], y = g[3] + i * g[4] + j * g[5];
      w = std::min(w, x), e = std::max(e, x), s = std::min(s, y), n = std::max(n, y);
    }
  return {w, s, e, n};
}

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

}  // namespace

Imagery load_imagery(const Heightfield& hf, const std::string& path, int max_side) {
  {
    static std::once_flag once;
    std::call_once(once, [] { GDALAllRegister(); });
  }
  QuietGdal quiet;
  Dataset src(GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  if (!src) throw DemError(path, "imagery cannot be read: " + last_error("not a recognised raster format"));
  auto* h = static_cast<GDALDatasetH>(src.get());
  double gt[6];
  const bool georeferenced = GDALGetGeoTransform(h, gt) == CE_None && GDALGetSpatialRef(h) != nullptr;

  Imagery out;
  Dataset use;  // what is read: the source, or its warp onto the DEM's footprint
  if (georeferenced && hf.georef && !hf.georef->crs_wkt.empty()) {
    const auto b = dem_bounds(hf);
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
      throw DemError(path, "imagery does not overlap the DEM (imagery " + num(sx) + ".." + num(sx1) + " x " + num(sy) +
                               ".." + num(sy1) + ", DEM " + num(b[0]) + ".." + num(b[2]) + " x " + num(b[1]) + ".." +
                               num(b[3]) + " in the DEM's CRS)");
    const double per_x = (b[2] - b[0]) / std::abs(suggested[1]), per_y = (b[3] - b[1]) / std::abs(suggested[5]);
    out.width = std::clamp(int(std::lround(per_x)), hf.width, max_side);
    out.height = std::clamp(int(std::lround(per_y)), hf.height, max_side);
    const std::vector<std::string> args = {"-of", "MEM", "-t_srs", hf.georef->crs_wkt, "-te", num(b[0]), num(b[1]),
                                           num(b[2]), num(b[3]), "-ts", std::to_string(out.width),
                                           std::to_string(out.height), "-r", "bilinear", "-dstalpha"};
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    GDALWarpAppOptions* options = GDALWarpAppOptionsNew(argv.data(), nullptr);
    int usage_error = 0;
    CPLErrorReset();
    use.reset(GDALWarp("", nullptr, 1, &h, options, &usage_error));
    GDALWarpAppOptionsFree(options);
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
  auto* ds = static_cast<GDALDatasetH>(use ? use.get() : src.get());
  auto rgb = read_rgb(ds, path);
  if (out.warped) {  // the destination alpha band says where the image covers the footprint
    const int bands = GDALGetRasterCount(ds);
    std::vector<std::uint8_t> alpha(std::size_t(out.width) * out.height);
    if (GDALRasterIO(GDALGetRasterBand(ds, bands), GF_Read, 0, 0, out.width, out.height, alpha.data(), out.width,
                     out.height, GDT_Byte, 0, 0) != CE_None)
      throw DemError(path, "imagery coverage read failed: " + last_error("unknown GDAL error"));
    for (std::size_t p = 0; p < alpha.size(); ++p)
      if (alpha[p] == 0) {
        ++out.uncovered;
        rgb[3 * p] = rgb[3 * p + 1] = rgb[3 * p + 2] = 128;
      }
  }
  // North row first in the raster; south first in the DEM's texture.
  out.rgb.resize(rgb.size());
  const std::size_t row = std::size_t(out.width) * 3;
  for (int y = 0; y < out.height; ++y)
    std::copy_n(rgb.begin() + std::ptrdiff_t(y * row), row, out.rgb.begin() + std::ptrdiff_t((out.height - 1 - y) * row));
  return out;
}

}  // namespace ig::terrain
