#pragma once
// A regular grid of terrain heights in metres, plus where it sits on Earth.
//
// Terrain-local frame (used everywhere in the IG): x east, y north, z up, in
// metres; sample (i, j) sits at (i * spacing_x_m, j * spacing_y_m, at(i, j)).
// Row j = 0 is the SOUTH edge (files store north first; loaders flip).

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "options/terrain_options.h"

namespace ig::water {
class WaterMap;  // water/water_map.h
}

namespace ig::terrain {

struct PagedHeights;  // terrain/paged_heights.h
struct TileMisses;    // terrain/height_tile_cache.h

// Affine map from terrain-local grid indices to the DEM's own CRS, kept so
// geodetic poses can be placed on the grid (GDAL geotransform convention,
// but for our south-up row order: crs = gt[0] + i*gt[1] + j*gt[2], ...).
struct GeoReference {
  std::string crs_wkt;                  // the DEM's CRS as WKT
  std::string crs_name;                 // short name, e.g. "EPSG:4326" or "WGS 84"
  bool geographic = false;              // lat/lon degrees (true) or projected metres
  std::array<double, 6> grid_to_crs{};  // (i, j) sample centre -> CRS x, y
};

struct Heightfield {
  int width = 0;   // samples west -> east
  int height = 0;  // samples south -> north
  double spacing_x_m = 1.0;
  double spacing_y_m = 1.0;
  std::vector<float> heights;  // width * height, row-major, row 0 = south; empty when paged
  // Set for a DEM whose heights exceed the memory budget: the
  // samples are paged from the source by a tile cache, and the overview and
  // min/max pyramid were built at load (terrain/paged_heights.h). at() and
  // everything built on it read through it; code that reads `heights`
  // directly checks has_whole_heights() first.
  std::shared_ptr<const PagedHeights> paged;

  // Statistics filled by finalize_stats().
  float min_m = 0.0f;
  float max_m = 0.0f;
  double mean_m = 0.0;
  std::int64_t nodata_count = 0;  // samples that were nodata in the file and got filled
  // GDAL loads: how the voids were filled (terrain/void_fill.h), and how
  // many were deep (no valid sample within its search distance).
  std::optional<options::VoidFillOptions> void_fill;
  std::int64_t deep_void_count = 0;

  std::optional<GeoReference> georef;
  // Where the terrain has water (terrain.water, water/water_setup.h): set
  // only when it has at least one body; the sample heights under it are its
  // levels.
  std::shared_ptr<const water::WaterMap> water;
  std::string source;  // file path, folder of tiles or generator description, for logs
  int source_tiles = 0;       // > 0: mosaicked from this many tiles (terrain/dem_mosaic.h)
  int reprojected_tiles = 0;  // of which reprojected to the first tile's CRS
  // Set only in a resident-only view (resident_only()): paged reads that
  // must not wait count here.
  TileMisses* resident_misses = nullptr;

  float at(int i, int j) const { return paged ? paged_at(i, j) : heights[static_cast<std::size_t>(j) * width + i]; }
  // For writing a heightfield that is not paged.
  float& ref(int i, int j) { return heights[static_cast<std::size_t>(j) * width + i]; }
  // All samples are in `heights` (not paged).
  bool has_whole_heights() const {
    return !paged && heights.size() == static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
  // Every sample readable through at(): whole or paged.
  bool has_samples() const { return paged || has_whole_heights(); }
  // Clamped lookup: outside samples take the nearest edge sample.
  float at_clamped(int i, int j) const;
  double extent_x_m() const { return (width - 1) * spacing_x_m; }
  double extent_y_m() const { return (height - 1) * spacing_y_m; }
  // Bilinear height at local (x, y) metres (clamped to the grid).
  double sample_bilinear(double x_m, double y_m) const;
  // Height on the rendered surface (the two triangles per quad, split along
  // the (i,j)-(i+1,j+1) diagonal) at local (x, y) metres, clamped.
  double sample_surface(double x_m, double y_m) const;

  void finalize_stats();

  // A paged heightfield read without waiting (a live frame): a sample whose
  // tile is not resident queues the tile, counts in `misses` and reads the
  // overview's height there instead, so the caller checks misses.count and
  // drops what it computed. A copy sharing the tiles (nothing else: no
  // georeference or source); `misses` must outlive it. Paged heightfields
  // only (std::logic_error otherwise: whole heights never wait).
  Heightfield resident_only(TileMisses& misses) const;

  // Georeferenced grids: the outer sample edges (half a sample beyond the
  // corner sample centres) in the DEM's CRS: west, south, east, north.
  std::optional<std::array<double, 4>> crs_bounds() const;

 private:
  float paged_at(int i, int j) const;
};

}  // namespace ig::terrain
