#pragma once
// Terrain source settings, one struct each for every place that sets them:
// the scenario file's terrain block (io/scenario.cpp), the DEM loader
// (visual/terrain/dem_loader.h) and the terrain generator
// (visual/terrain/synthetic_terrain.h). Plain data, no GL.

#include <array>
#include <optional>
#include <string>

namespace ig::options {

// How nodata samples (voids) are filled at load (terrain.void_fill): GDAL's
// GDALFillNodata, the engine of `gdal_fillnodata.py -md max_distance -si
// smoothing_iterations` (terrain/void_fill.h, docs/terrain-data.md "Nodata").
struct VoidFillOptions {
  // How far (samples) the fill looks for valid samples in each direction,
  // 1 ... kMaxVoidSearch. Voids farther than this from any valid sample are
  // "deep": GDAL leaves them and they are filled layer by layer from the
  // filled samples around them.
  int max_distance = 400;
  // 3x3 mean passes over the filled samples after the interpolation, which
  // soften its straight-line artefacts, 0 ... kMaxVoidSmoothing.
  int smoothing_iterations = 2;
  // Limits: a paged tile with voids is read with a halo of up to
  // max_distance + smoothing_iterations + 257 samples (terrain/gdal_tile_reader.h).
  static constexpr int kMaxVoidSearch = 1024;
  static constexpr int kMaxVoidSmoothing = 32;
};

// How a DEM file is read (terrain.encoding, scale, offset, spacing_m).
struct DemLoadOptions {
  // "auto": PNG files (by signature) go to png16 (1-channel 16-bit) or
  // terrain-rgb (8-bit RGB/RGBA); everything else goes to GDAL.
  // "terrain-rgb" / "png16": force that image decoding (OpenImageIO).
  // "gdal": force GDAL.
  std::string encoding = "auto";
  double scale = 1.0;   // png16 only: metres = value * scale + offset
  double offset = 0.0;  // png16 only
  // Overrides the sample spacing (both axes, metres) for any format. Images
  // need it to have real-world spacing; they default to 1 m.
  std::optional<double> spacing_m;
  // Memory budget for the heights (terrain.memory_budget_mb): a GDAL DEM
  // whose float heights exceed it is paged from the file in tiles of
  // page_tile samples a side into a cache of at most this size
  // (terrain/paged_heights.h, docs/terrain-data.md "Paged heights").
  int memory_budget_mb = 2048;
  int page_tile = 256;
  // What the file's heights are above (terrain.vertical_datum): "geoid"
  // (EGM96, i.e. about mean sea level, as SRTM: used as stored) or
  // "ellipsoid" (WGS 84: converted to above the geoid at load,
  // terrain/geoid_correction.h).
  std::string vertical_datum = "geoid";
  // GDAL DEMs' voids (terrain.void_fill).
  VoidFillOptions void_fill;
};

// The fractal terrain generator (terrain.generator).
struct SyntheticTerrainOptions {
  int size = 1025;            // samples per side: 2^n + 1, 3 ... 16385
  unsigned seed = 1;          // any value; different seeds give different terrain
  double spacing_m = 30.0;    // sample spacing (both axes), > 0
  double relief_m = 1500.0;   // max - min height, >= 0
  double base_m = 0.0;        // lowest height
  int octaves = 9;            // noise octaves, 1 ... 24
  double ridge_weight = 0.5;  // 0 = rolling fBm hills, 1 = pure ridged mountains
  // WGS84 latitude/longitude of the south-west sample: the session
  // georeferences the generated terrain with it so it takes geodetic poses
  // (CIGI, FlightGear). The generator itself ignores it.
  std::optional<std::array<double, 2>> origin_lat_lon;
};

}  // namespace ig::options
