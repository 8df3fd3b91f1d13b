#pragma once
// DEMs packed into ordinary images (png16, terrain-rgb), read through
// OpenImageIO; load_dem (terrain/dem_loader.h) chooses this reader for PNG
// input or an explicit image encoding. Also the raster size limits every
// reader checks, so each failure names the same limits.

#include <cstdint>
#include <string>

#include "terrain/dem_loader.h"

namespace ig::terrain {

// encoding: "png16", "terrain-rgb" or "auto" (chosen from the image layout).
// Throws DemError on any failure.
Heightfield load_with_oiio(const std::string& path, const DemLoadOptions& opts, std::string encoding);

// "WxH", for messages.
std::string size_text(std::int64_t w, std::int64_t h);

// Throws DemError when the raster is smaller than 2x2 or beyond the limits
// (65537 per side and 2^30 samples). paged: the heights are paged, so only
// the side limit applies.
void check_size(const std::string& path, std::int64_t w, std::int64_t h, bool paged = false);

}  // namespace ig::terrain
