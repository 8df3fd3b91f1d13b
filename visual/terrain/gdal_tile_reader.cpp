#include "terrain/gdal_tile_reader.h"

#include <cpl_error.h>

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

std::int64_t GdalTileReader::read(int x0, int y0, int w, int h, float* out) {
  gdal::QuietErrors quiet;
  std::vector<float> buf(static_cast<std::size_t>(w) * h);
  CPLErrorReset();
  // File rows run north first: our rows [y0, y0 + h) are file rows [H - y0 - h, H - y0).
  if (GDALRasterIO(band_, GF_Read, x0, height_ - y0 - h, w, h, buf.data(), w, h, GDT_Float32, 0, 0) != CE_None)
    throw std::runtime_error(path_ + ": read failed at samples " + std::to_string(x0) + "," + std::to_string(y0) +
                             ": " + gdal::last_error());
  std::vector<std::uint8_t> state;
  std::size_t valid = 0;
  for (float v : buf) valid += dec_.valid(v);
  if (valid < buf.size()) {
    state.resize(buf.size());
    for (std::size_t k = 0; k < buf.size(); ++k) state[k] = dec_.valid(buf[k]);
  }
  if (dec_.scale != 1.0 || dec_.offset != 0.0 || dec_.unit_m != 1.0)
    for (std::size_t k = 0; k < buf.size(); ++k)
      if (state.empty() || state[k]) buf[k] = float((buf[k] * dec_.scale + dec_.offset) * dec_.unit_m);
  std::int64_t voids = 0;
  if (!state.empty()) {
    voids = fill_voids(buf, state, w, h);
    if (valid == 0)
      for (float& v : buf) v = 0.0f;  // nothing to fill from inside the rectangle
  }
  for (int r = 0; r < h; ++r)  // flip: file row h-1-r is our row r
    std::copy(buf.begin() + std::ptrdiff_t(h - 1 - r) * w, buf.begin() + std::ptrdiff_t(h - r) * w,
              out + std::size_t(r) * w);
  return voids;
}

}  // namespace ig::terrain
