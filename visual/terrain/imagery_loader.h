#pragma once
// Imagery draped over a DEM: any RGB (or grey) raster GDAL reads. A
// georeferenced image (GeoTIFF ...) of any size, extent and CRS is warped
// onto the DEM's footprint (its outer sample edges, in the DEM's CRS), so
// texture coordinate (s + 0.5) / dem_size lands on sample s as the shaders
// expect; an image without georeferencing is taken to span the DEM exactly
// (the old behaviour). No GL here. docs/terrain-data.md.

#include <cstdint>
#include <string>
#include <vector>

#include "terrain/heightfield.h"

namespace ig::terrain {

struct Imagery {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3, row 0 = SOUTH (as the DEM)
  bool warped = false;            // reprojected / resampled onto the DEM's footprint
  std::int64_t uncovered = 0;     // pixels of the footprint the image does not cover (left grey)
};

// Loads `path` for `hf`, at most max_side pixels a side (the GL texture
// limit). Throws DemError ("<path>: <reason>") for an unreadable file, an
// image with no colour bands, or a georeferenced image that does not overlap
// the DEM at all.
Imagery load_imagery(const Heightfield& hf, const std::string& path, int max_side);

}  // namespace ig::terrain
