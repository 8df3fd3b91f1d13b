#include "terrain/gdal_tile_reader.h"

#include <cpl_error.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "terrain/void_fill.h"
#include "terrain/void_fill_halo.h"

namespace ig::terrain {

bool SampleDecoding::valid(float v) const { return std::isfinite(v) && v != -32768.0f && v != nodata; }

GdalTileReader::GdalTileReader(const std::string& path, SampleDecoding decoding, VoidFillOptions void_fill)
    : path_(path), dec_(std::move(decoding)), fill_(void_fill) {
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
  const int gdal_reach = full_fill_halo(fill_);
  std::vector<std::int32_t> deep_layers;
  for (int halo = std::min(gdal_reach, std::max(kFirstVoidHalo, fill_.smoothing_iterations + 6));;) {
    const int wx0 = std::max(0, x0 - halo), wy0 = std::max(0, y0 - halo);
    const int ww = std::min(width_, x0 + w + halo) - wx0, wh = std::min(height_, y0 + h + halo) - wy0;
    read_decoded(wx0, wy0, ww, wh, buf, state);
    // The whole DEM in the window: the whole load's fill itself.
    const bool whole = ww == width_ && wh == height_;
    if (!whole) {
      const FillWindow window{ww, wh, x0 - wx0, y0 - wy0, w, h, wx0 + ww == width_};
      const int need = exact_fill_halo(state, window, fill_);
      if (need > halo) {
        halo = need;
        continue;
      }
    }
    fill_voids(buf, state, ww, wh, fill_, &deep_layers);
    auto window_index = [&](int r, int c) { return std::size_t(y0 - wy0 + r) * ww + std::size_t(x0 - wx0 + c); };
    std::int32_t deepest = 0;
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) deepest = std::max(deepest, deep_layers[window_index(r, c)]);
    // A deep sample of layer d reads the GDAL-filled samples d around it,
    // and those read GDAL's reach around them.
    const int most = gdal_reach + kMaxExactDeepLayer;
    if (!whole && deepest > 0 && halo < most) {
      const int need = deepest == kUnfilledLayer ? most : std::min(most, gdal_reach + int(deepest));
      if (need > halo) {
        halo = need;
        continue;
      }
    }
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) {
        const std::size_t k = window_index(r, c);
        const std::int32_t layer = deep_layers[k];
        out[std::size_t(r) * w + c] = layer == kUnfilledLayer ? 0.0f : buf[k];  // no valid sample in the window
        voids.deep += layer > 0;
        voids.inexact += !whole && layer > 0 && layer > halo - gdal_reach;
      }
    return voids;
  }
}

}  // namespace ig::terrain
