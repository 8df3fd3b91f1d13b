#pragma once
// The user's water data (terrain.water as a path) brought onto the DEM's
// grid with GDAL's own tools. No GL.
//
//  * Vector (any OGR layer of polygons: GeoJSON, Shapefile, GeoPackage, ...;
//    the first layer): each polygon feature is a body, reprojected to the
//    DEM's CRS (OGR) and burned into the grid by GDALRasterizeGeometries, as
//    `gdal_rasterize` burns it: a sample is water when its centre lies
//    inside. A later polygon over an earlier one wins.
//  * Raster (any GDAL raster, band 1; non-zero = water, nodata = land):
//    warped onto the DEM's grid by gdalwarp (nearest neighbour); each
//    4-connected region of water samples is a body.
// Levels: a numeric polygon attribute when one is named, else from the DEM
// (water/water_levels.h).
//
// Every failure is a WaterFileError "<path>: <reason>": no such file, a file
// GDAL cannot open, no CRS, a DEM without georeferencing, no overlap with the
// DEM, an empty layer, a layer with no polygons, a missing or non-numeric
// level attribute.

#include <optional>
#include <stdexcept>
#include <string>

#include "terrain/heightfield.h"
#include "water/water_map.h"

namespace ig::water {

struct WaterFileError : std::runtime_error {
  WaterFileError(const std::string& path, const std::string& reason);
};

// The water of `path` on hf's grid, with levels. The map's source() is the path.
WaterMap read_water_file(const terrain::Heightfield& hf, const std::string& path,
                         const std::optional<std::string>& level_attribute = std::nullopt);

}  // namespace ig::water
