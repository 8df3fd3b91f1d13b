#pragma once
// Where the terrain's water comes from (terrain.water, docs/scenario.md): one
// struct for the scenario file, ig serve --config, ig info and the loader
// (water/water_setup.h). Plain data, no GL.

#include <optional>
#include <string>

namespace ig::options {

enum class WaterSource {
  Auto,  // the sea and SWBD-style lakes found in the DEM (water/water_detection.h)
  Off,   // no water
  File,  // the user's water data: a GDAL raster (non-zero = water) or OGR polygons
};

struct WaterOptions {
  WaterSource source = WaterSource::Auto;
  std::string file;  // File: its path (environment variables expanded)
  // File, polygons: a numeric attribute giving each polygon's water level
  // (metres, the DEM's vertical datum); unset: chosen from the DEM.
  std::optional<std::string> level_attribute;
};

}  // namespace ig::options
