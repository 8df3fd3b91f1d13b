#pragma once
// Imagery draped over a DEM: any RGB (or grey) raster GDAL reads. A
// georeferenced image (GeoTIFF ...) of any size, extent and CRS is warped
// onto the DEM's footprint (its outer sample edges, in the DEM's CRS), so
// texture coordinate (s + 0.5) / dem_size lands on sample s as the shaders
// expect; an image without georeferencing is taken to span the DEM exactly.
// Georeferenced imagery finer than the texture limit is paged at full
// resolution: tiles are read on demand from a GDAL
// warped VRT onto the footprint (the same extent, size, bilinear resampling
// and destination alpha as the in-memory warp of imagery that fits) into an
// RgbTileCache within a byte budget (for the scene's imagery window,
// render/imagery_window_texture.h); one pass over it in strips at load makes
// the overview that fits one texture and counts the uncovered pixels. No GL
// here. docs/terrain-data.md.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "terrain/height_tile_cache.h"
#include "terrain/heightfield.h"

namespace ig::terrain {

// Full-resolution imagery beyond the texture limit, paged.
struct PagedImagery {
  // full_width() x full_height() pixels, row 0 = south; uncovered pixels
  // grey (128), as in the one-texture image.
  std::shared_ptr<const RgbTileCache> cache;
  // Tiles whose read failed after the load (corrupt or vanished file): drawn
  // grey, counted here and logged (the first few), never thrown.
  std::shared_ptr<std::atomic<std::int64_t>> failed_tiles = std::make_shared<std::atomic<std::int64_t>>(0);
};

// How imagery beyond the texture limit is paged.
struct ImageryPaging {
  std::size_t budget_bytes = std::size_t(512) << 20;  // terrain.imagery_budget_mb
  int tile = 256;                                     // pixels a tile side
  // The window the cache serves (render/imagery_window_texture.h): the
  // budget is raised to at least what it needs with a tile of margin
  // (imagery_window_budget), or the window could never move.
  int window_side = 4096;
};
std::size_t imagery_window_budget(int window_side, int tile);

struct Imagery {
  // What one texture holds over the whole footprint: the image, or beyond
  // the limit its overview: pixel k the mean of full-resolution pixels
  // [k * full_step, (k + 1) * full_step) (fewer in the last row and column
  // when the full size is not a multiple), so the overview spans
  // width * full_step >= full_width() full pixels.
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3, row 0 = SOUTH (as the DEM)
  bool warped = false;            // reprojected / resampled onto the DEM's footprint
  std::int64_t uncovered = 0;     // full-resolution pixels of the footprint the image does not cover (grey)
  // Beyond the limit only: the full resolution over the footprint, paged;
  // null when the image fits (then full size = width x height).
  int full_step = 1, full_w = 0, full_h = 0;
  std::shared_ptr<const PagedImagery> paged;
  int full_width() const { return full_step > 1 ? full_w : width; }
  int full_height() const { return full_step > 1 ? full_h : height; }
};

// Loads `path` for `hf`. A georeferenced image gets about its own resolution
// over the DEM (at least one pixel per DEM sample); beyond max_side (the
// texture limit) a side it is paged (as `paging` says) and gets an overview
// within max_side; resident memory stays near overview + budget. An image
// without georeferencing must fit max_side. Throws DemError ("<path>:
// <reason>") for an unreadable file, an image with no colour bands, or a
// georeferenced image that does not overlap the DEM at all.
Imagery load_imagery(const Heightfield& hf, const std::string& path, int max_side, const ImageryPaging& paging = {});

}  // namespace ig::terrain
