#pragma once
// Reads rectangles of a single-band GDAL raster as DEM heights in metres,
// south row first, decoded as the whole-array load does (band scale /
// offset and vertical unit applied to valid samples; voids as in
// terrain/dem_loader.h). Used by the paged loader for its pass over the
// source and by the tile cache for every page-in (issue 16). Owns its own
// dataset handle; not thread-safe (the tile cache calls it on one thread at
// a time). Internal to ig_terrain.
//
// Voids are filled within the rectangle read (fill_voids over that
// rectangle alone; a rectangle with no valid sample becomes 0 m), so a
// paged DEM with voids can differ from its whole-array load near tile
// edges; void-free DEMs read identically.

#include <cstdint>
#include <string>

#include "terrain/gdal_support.h"

namespace ig::terrain {

struct SampleDecoding {
  float nodata = -32768.0f;  // the band's nodata value (the SRTM void marker when it has none)
  double scale = 1.0, offset = 0.0, unit_m = 1.0;
  bool valid(float v) const;
};

class GdalTileReader {
 public:
  // Opens `path` (throws std::runtime_error naming it on failure).
  GdalTileReader(const std::string& path, SampleDecoding decoding);
  int width() const { return width_; }
  int height() const { return height_; }
  // Samples [x0, x0 + w) x [y0, y0 + h) (row y0 = south) into out (w * h,
  // row-major). Returns the void samples filled. Throws std::runtime_error.
  std::int64_t read(int x0, int y0, int w, int h, float* out);

 private:
  std::string path_;
  gdal::Dataset ds_;
  GDALRasterBandH band_ = nullptr;
  int width_ = 0, height_ = 0;
  SampleDecoding dec_;
};

}  // namespace ig::terrain
