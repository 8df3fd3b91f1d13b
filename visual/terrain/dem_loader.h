#pragma once
// Loading real elevation data (DEMs) into a Heightfield.
//
// Two back ends:
//  * GDAL, for every georeferenced single-band raster GDAL opens: GeoTIFF
//    (int16 / uint16 / float32 ...), SRTM .hgt, USGS ASCII DEM, ESRI ASCII
//    grid (.asc), ... Spacing and georeferencing come from the file.
//  * OpenImageIO, for DEMs packed into ordinary PNG images: 16-bit grayscale
//    ("png16": metres = value * scale + offset) and Mapbox terrain-RGB
//    ("terrain-rgb": metres = -10000 + (R*65536 + G*256 + B) * 0.1). Images
//    carry no spacing: it is DemLoadOptions::spacing_m, else 1 m, and the
//    result has no georef.
//
// Rows are flipped on load so row 0 is the SOUTH edge (files store north
// first). Nodata / void samples are filled (see load_dem) and counted.
// Every failure is a DemError with a one-line "<path>: <reason>" message; a
// bad file never crashes the loader and never yields a partial grid.
// See docs/terrain-data.md.

#include <optional>
#include <stdexcept>
#include <string>

#include "options/terrain_options.h"
#include "terrain/heightfield.h"

namespace ig::terrain {

struct DemError : std::runtime_error {
  DemError(const std::string& path, const std::string& reason);
  const std::string& path() const { return path_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string path_;
  std::string reason_;
};

using DemLoadOptions = options::DemLoadOptions;  // options/terrain_options.h

// Loads a DEM; throws DemError on any failure (message "<path>: <reason>").
// A folder is read as a mosaic of the DEM tiles in it (terrain/dem_mosaic.h).
//
// Nodata: a sample is void when it equals the band's nodata value, is NaN or
// +-Inf, or is -32768 (the SRTM void marker; no real elevation is that low).
// Voids are filled as GDAL's gdal_fillnodata.py fills them (GDALFillNodata
// with opts.void_fill: inverse-distance interpolation from the nearest valid
// samples, then smoothing passes); deep voids beyond its search distance
// layer by layer from the filled rim (terrain/void_fill.h). The number of
// filled samples is Heightfield::nodata_count, the deep ones
// deep_void_count. A grid with no valid sample at all is an error.
Heightfield load_dem(const std::string& path, const DemLoadOptions& opts = {});

// One JSON object (single line) describing a loaded heightfield: width,
// height, spacing_x_m, spacing_y_m, min_m, max_m, mean_m, nodata_count,
// for GDAL loads "void_fill" ({"algorithm": "GDALFillNodata", "max_distance",
// "smoothing_iterations", "deep_count", "deep_fill": "layers"}), crs
// (short name or null), geographic, source, and for georeferenced grids
// "corners" ({"sw","se","nw","ne"}: [x, y] CRS coordinates of the corner
// sample centres) and "bounds" (outer pixel edges: west, south, east, north);
// for a folder of tiles also "tiles" and "reprojected_tiles"; with `water`
// (what terrain.water found or read, water/water_setup.h) "water": its
// source, number of bodies, water samples and area, and each body (kind,
// level_m, samples, area_km2, its bounding box in samples and, georeferenced,
// its centre in the DEM's CRS), the largest first; null when water is off.
std::string dem_info_json(const Heightfield& hf, const water::WaterMap* water = nullptr, bool water_off = false);

// Metres per unit of latitude / longitude at geodetic latitude lat_deg on an
// ellipsoid (semi-major axis a, inverse flattening inv_f; inv_f = 0 is a
// sphere), for an angular unit of unit_rad radians (pi/180 for degrees).
// Used for the ground spacing of geographic DEMs; exposed for tests.
struct MetresPerAngle {
  double north;  // along the meridian
  double east;   // along the parallel
};
MetresPerAngle metres_per_angle(double lat_deg, double a = 6378137.0,
                                double inv_f = 298.257223563,
                                double unit_rad = 0.017453292519943295);

}  // namespace ig::terrain
