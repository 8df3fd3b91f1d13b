#pragma once
// What every GDAL reader here needs (DEM files, folders of tiles, imagery):
// one-time driver registration, GDAL's own messages silenced while we turn
// failures into DemError lines, datasets closed by RAII, and gdalwarp run
// with command-line style arguments. Internal to ig_terrain.

#include <gdal.h>

#include <memory>
#include <string>
#include <vector>

namespace ig::terrain::gdal {

void register_once();

// Silences GDAL's stderr output on this thread for the scope; failures are
// read from last_error() instead.
class QuietErrors {
 public:
  QuietErrors();
  ~QuietErrors();
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;
};

struct DatasetCloser {
  void operator()(void* ds) const {
    if (ds) GDALClose(static_cast<GDALDatasetH>(ds));
  }
};
using Dataset = std::unique_ptr<void, DatasetCloser>;
inline GDALDatasetH handle(const Dataset& ds) { return static_cast<GDALDatasetH>(ds.get()); }

// A message on one line: newlines and tabs to spaces, outer spaces and a
// final full stop trimmed (GDAL and OpenImageIO sometimes return several lines).
std::string one_line(std::string s);
// GDAL's last error message on one line, or `otherwise` when it said nothing.
std::string last_error(const char* otherwise = "");
// A number as an exact command-line argument (%.17g).
std::string number_arg(double v);
// gdalwarp of `src` into `dest` (a file, /vsimem/ path, or "" with -of MEM)
// with gdalwarp's arguments; null on failure (last_error() says why).
Dataset warp(GDALDatasetH src, const std::string& dest, const std::vector<std::string>& args);

}  // namespace ig::terrain::gdal
