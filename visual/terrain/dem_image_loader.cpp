#include "terrain/dem_image_loader.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdint>
#include <new>
#include <vector>

#include "terrain/gdal_support.h"
#include "terrain/huge_pages.h"

namespace ig::terrain {

namespace {

constexpr std::int64_t kMaxSide = 65537;
constexpr std::int64_t kMaxSamples = std::int64_t{1} << 30;

using gdal::one_line;

const char* kImageEncodings =
    "supported image encodings: png16 (16-bit grayscale), terrain-rgb (8-bit RGB/RGBA "
    "Mapbox terrain-RGB); other rasters load through GDAL";

}  // namespace

Heightfield load_with_oiio(const std::string& path, const DemLoadOptions& opts,
                           std::string encoding) {
  if (opts.vertical_datum == "ellipsoid")
    throw DemError(path, "vertical_datum \"ellipsoid\" needs a georeferenced DEM (read through GDAL), not an image");
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);  // never premultiply RGB by alpha
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) {
    const std::string msg = one_line(OIIO::geterror());
    throw DemError(path, "not a recognised raster format" +
                             (msg.empty() ? std::string() : " (" + msg + ")"));
  }
  const OIIO::ImageSpec spec = in->spec();
  const int nch = spec.nchannels;
  const OIIO::TypeDesc fmt = spec.format;
  const bool is16 = fmt == OIIO::TypeDesc::UINT16 || fmt == OIIO::TypeDesc::INT16;
  const bool is8 = fmt == OIIO::TypeDesc::UINT8;
  const std::string layout = std::to_string(nch) + "-channel " + std::string(fmt.c_str());

  if (encoding == "auto") {
    if (is16 && (nch == 1 || nch == 2))
      encoding = "png16";
    else if (is8 && (nch == 3 || nch == 4))
      encoding = "terrain-rgb";
    else if (is8 && (nch == 1 || nch == 2))
      throw DemError(path, "8-bit grayscale image is not a DEM encoding (" +
                               std::string(kImageEncodings) + ")");
    else
      throw DemError(path, "unsupported image layout " + layout + " (" + kImageEncodings +
                               ")");
  } else if (encoding == "png16" && !is16) {
    throw DemError(path, "png16 needs a 16-bit grayscale image, this is " + layout);
  } else if (encoding == "terrain-rgb" && !(is8 && nch >= 3)) {
    throw DemError(path, "terrain-rgb needs an 8-bit RGB or RGBA image, this is " + layout);
  }
  if (spec.depth > 1) throw DemError(path, "volume images are not DEMs");
  check_size(path, spec.width, spec.height);
  const int w = spec.width, ht = spec.height;
  const std::size_t n = std::size_t(w) * std::size_t(ht);

  Heightfield hf;
  hf.width = w;
  hf.height = ht;
  hf.source = path;
  const double spacing = opts.spacing_m.value_or(1.0);
  hf.spacing_x_m = hf.spacing_y_m = spacing;
  try {
    reserve_in_huge_pages(hf.heights, n);  // scattered queries: terrain/huge_pages.h
    hf.heights.resize(n);
    if (encoding == "png16") {
      std::vector<std::uint16_t> raw(n);
      if (!in->read_image(0, 0, 0, 1, fmt, raw.data())) {
        const std::string msg = one_line(in->geterror());
        throw DemError(path, "read failed (truncated or corrupt image?)" +
                                 (msg.empty() ? std::string() : ": " + msg));
      }
      const bool is_signed = fmt == OIIO::TypeDesc::INT16;
      for (int r = 0; r < ht; ++r) {
        const std::uint16_t* src = raw.data() + std::size_t(r) * w;
        float* dst = hf.heights.data() + std::size_t(ht - 1 - r) * w;
        for (int i = 0; i < w; ++i) {
          const double v = is_signed ? double(std::int16_t(src[i])) : double(src[i]);
          dst[i] = float(v * opts.scale + opts.offset);
        }
      }
    } else {  // terrain-rgb
      std::vector<std::uint8_t> raw(n * 3);
      if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, raw.data())) {
        const std::string msg = one_line(in->geterror());
        throw DemError(path, "read failed (truncated or corrupt image?)" +
                                 (msg.empty() ? std::string() : ": " + msg));
      }
      for (int r = 0; r < ht; ++r) {
        const std::uint8_t* src = raw.data() + std::size_t(r) * w * 3;
        float* dst = hf.heights.data() + std::size_t(ht - 1 - r) * w;
        for (int i = 0; i < w; ++i) {
          const std::uint32_t code = (std::uint32_t(src[3 * i]) << 16) |
                                     (std::uint32_t(src[3 * i + 1]) << 8) | src[3 * i + 2];
          dst[i] = float(-10000.0 + double(code) * 0.1);
        }
      }
    }
  } catch (const std::bad_alloc&) {
    throw DemError(path, "out of memory for a " + size_text(w, ht) + " grid");
  }
  for (float v : hf.heights)
    if (!std::isfinite(v))
      throw DemError(path, "decoded heights are not finite (check --scale / --offset)");
  hf.finalize_stats();
  return hf;
}

std::string size_text(std::int64_t w, std::int64_t h) {
  return std::to_string(w) + "x" + std::to_string(h);
}

void check_size(const std::string& path, std::int64_t w, std::int64_t h, bool paged) {
  if (w < 2 || h < 2)
    throw DemError(path, "raster size " + size_text(w, h) +
                             " is too small (a DEM needs at least 2x2 samples)");
  if (w > kMaxSide || h > kMaxSide || (w * h > kMaxSamples && !paged))
    throw DemError(path, "raster size " + size_text(w, h) +
                             " is too large (limit 65537 per side and 2^30 samples)");
}

}  // namespace ig::terrain
