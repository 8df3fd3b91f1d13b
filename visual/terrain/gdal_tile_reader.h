#pragma once
// Reads rectangles of a single-band GDAL raster as DEM heights in metres,
// south row first, decoded as the whole-array load does (band scale /
// offset and vertical unit applied to valid samples; voids as in
// terrain/dem_loader.h). Used by the paged loader for its pass over the
// source and by the tile cache for every page-in. Owns its own
// dataset handle; not thread-safe (the tile cache calls it on one thread at
// a time). Internal to ig_terrain.
//
// Voids are filled as the whole-array load fills them (terrain/void_fill.h),
// bit for bit for all but the deepest: a rectangle with voids is read again
// with a halo around it (clipped to the DEM), filled, then cropped. The
// halo is what makes GDAL's values exact there (terrain/void_fill_halo.h):
// a few samples for small voids, max_distance + 1 + smoothing_iterations
// for large ones. Deep voids (beyond GDAL's reach, filled by layers) need
// their layer more, up to kMaxExactDeepLayer; the samples deeper than that
// may differ from the whole load and are counted (TileVoids::inexact; a
// window with no valid sample at all becomes 0 m). Void-free rectangles are
// read once, as is.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "terrain/gdal_support.h"
#include "terrain/geoid_correction.h"
#include "terrain/void_fill.h"

namespace ig::terrain {

// The halo a rectangle with voids is first read with (grown as it needs).
constexpr int kFirstVoidHalo = 32;
// Deep voids up to this many layers inside GDAL's reach fill exactly.
constexpr int kMaxExactDeepLayer = 256;

// What one read() filled.
struct TileVoids {
  std::int64_t filled = 0;   // void samples in the rectangle
  std::int64_t deep = 0;     // of those, beyond GDAL's search distance (filled by layers)
  std::int64_t inexact = 0;  // of those, deeper than kMaxExactDeepLayer: may differ from the whole load
};

struct SampleDecoding {
  float nodata = -32768.0f;  // the band's nodata value (the SRTM void marker when it has none)
  double scale = 1.0, offset = 0.0, unit_m = 1.0;
  // Ellipsoidal heights: the undulation subtracted from valid samples after
  // scale and units, before voids are filled (null: heights as stored).
  std::shared_ptr<const GeoidCorrection> geoid;
  bool valid(float v) const;
};

class GdalTileReader {
 public:
  // Opens `path` (throws std::runtime_error naming it on failure).
  GdalTileReader(const std::string& path, SampleDecoding decoding, VoidFillOptions void_fill);
  int width() const { return width_; }
  int height() const { return height_; }
  // Samples [x0, x0 + w) x [y0, y0 + h) (row y0 = south) into out (w * h,
  // row-major), voids filled. Throws std::runtime_error.
  TileVoids read(int x0, int y0, int w, int h, float* out);

 private:
  // The rectangle decoded, rows south first; `state` (1 valid, 0 void) left
  // empty when every sample is valid. Returns the number of void samples.
  std::int64_t read_decoded(int x0, int y0, int w, int h, std::vector<float>& buf, std::vector<std::uint8_t>& state);

  std::string path_;
  gdal::Dataset ds_;
  GDALRasterBandH band_ = nullptr;
  int width_ = 0, height_ = 0;
  SampleDecoding dec_;
  VoidFillOptions fill_;
};

}  // namespace ig::terrain
