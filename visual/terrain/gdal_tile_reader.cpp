#include "terrain/gdal_tile_reader.h"

#include <cpl_error.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "terrain/void_fill.h"

namespace ig::terrain {

bool SampleDecoding::valid(float v) const { return std::isfinite(v) && v != -32768.0f && v != nodata; }

GdalTileReader::GdalTileReader(const std::string& path, SampleDecoding decoding) : path_(path), dec_(decoding) {
  gdal::register_once();
  gdal::QuietErrors quiet;
  ds_.reset(GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  if (!ds_) throw std::runtime_error(path + ": cannot open for paging: " + gdal::last_error());
  band_ = GDALGetRasterBand(gdal::handle(ds_), 1);
  width_ = GDALGetRasterXSize(gdal::handle(ds_));
  height_ = GDALGetRasterYSize(gdal::handle(ds_));
}

std::int64_t GdalTileReader::read_decoded(int x0, int y0, int w, int h, std::vector<float>& buf,
                                          std::vector<std::uint8_t>& state) {
  gdal::QuietErrors quiet;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  std::vector<float> file(n);
  CPLErrorReset();
  // File rows run north first: our rows [y0, y0 + h) are file rows [H - y0 - h, H - y0).
  if (GDALRasterIO(band_, GF_Read, x0, height_ - y0 - h, w, h, file.data(), w, h, GDT_Float32, 0, 0) != CE_None)
    throw std::runtime_error(path_ + ": read failed at samples " + std::to_string(x0) + "," + std::to_string(y0) +
                             ": " + gdal::last_error());
  buf.resize(n);
  for (int r = 0; r < h; ++r)  // flip first, as the whole load does, so the fill sees the same grid
    std::copy(file.begin() + std::ptrdiff_t(h - 1 - r) * w, file.begin() + std::ptrdiff_t(h - r) * w,
              buf.begin() + std::ptrdiff_t(r) * w);
  std::size_t valid = 0;
  for (float v : buf) valid += dec_.valid(v);
  state.clear();
  if (valid < n) {
    state.resize(n);
    for (std::size_t k = 0; k < n; ++k) state[k] = dec_.valid(buf[k]);
  }
  if (dec_.scale != 1.0 || dec_.offset != 0.0 || dec_.unit_m != 1.0)
    for (std::size_t k = 0; k < n; ++k)
      if (state.empty() || state[k]) buf[k] = float((buf[k] * dec_.scale + dec_.offset) * dec_.unit_m);
  if (dec_.geoid) dec_.geoid->to_orthometric(x0, y0, w, h, buf.data(), state.empty() ? nullptr : state.data());
  return std::int64_t(n - valid);
}

TileVoids GdalTileReader::read(int x0, int y0, int w, int h, float* out) {
  std::vector<float> buf;
  std::vector<std::uint8_t> state;
  TileVoids voids;
  voids.filled = read_decoded(x0, y0, w, h, buf, state);
  if (voids.filled == 0) {
    std::copy(buf.begin(), buf.end(), out);
    return voids;
  }
  std::vector<std::int32_t> layers;
  for (int halo = kVoidHalo;;) {
    const int wx0 = std::max(0, x0 - halo), wy0 = std::max(0, y0 - halo);
    const int ww = std::min(width_, x0 + w + halo) - wx0, wh = std::min(height_, y0 + h + halo) - wy0;
    read_decoded(wx0, wy0, ww, wh, buf, state);
    fill_voids(buf, state, ww, wh, &layers);
    auto window_index = [&](int r, int c) { return std::size_t(y0 - wy0 + r) * ww + std::size_t(x0 - wx0 + c); };
    std::int32_t deepest = 0;
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) deepest = std::max(deepest, layers[window_index(r, c)]);
    // The whole DEM in the window: the whole load's fill itself.
    const bool whole = ww == width_ && wh == height_;
    if (deepest <= halo || whole || halo >= kMaxVoidHalo) {
      for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
          const std::size_t k = window_index(r, c);
          const bool unfilled = layers[k] == kUnfilledLayer;  // no valid sample in the window
          out[std::size_t(r) * w + c] = unfilled ? 0.0f : buf[k];
          voids.inexact += !whole && layers[k] > halo;
        }
      return voids;
    }
    halo = std::min(kMaxVoidHalo, deepest == kUnfilledLayer ? 4 * halo : int(deepest));
  }
}

}  // namespace ig::terrain
