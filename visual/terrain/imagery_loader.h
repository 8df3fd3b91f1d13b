#pragma once
// Imagery draped over a DEM: any RGB (or grey) raster GDAL reads. A
// georeferenced image (GeoTIFF ...) of any size, extent and CRS is warped
// onto the DEM's footprint (its outer sample edges, in the DEM's CRS), so
// texture coordinate (s + 0.5) / dem_size lands on sample s as the shaders
// expect; an image without georeferencing is taken to span the DEM exactly
// (the old behaviour). Georeferenced imagery finer than the texture limit is
// kept at full resolution (for the scene's imagery window, render/
// imagery_window_texture.h) plus an overview of it that fits one texture
// (issue 16). No GL here. docs/terrain-data.md.

#include <cstdint>
#include <string>
#include <vector>

#include "terrain/heightfield.h"

namespace ig::terrain {

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
  // Beyond the limit only: the full resolution over the footprint, row 0 =
  // south; empty when the image fits (then full size = width x height).
  int full_step = 1, full_w = 0, full_h = 0;
  std::vector<std::uint8_t> full_rgb;
  int full_width() const { return full_step > 1 ? full_w : width; }
  int full_height() const { return full_step > 1 ? full_h : height; }
};

// At most this many bytes of full-resolution imagery are held (RGB, in
// memory, not paged): finer imagery is resampled down to it (~18900^2 RGB;
// loading needs about 2.7 times that at its peak: the warp's RGBA and the read).
constexpr std::int64_t kMaxFullImageryBytes = std::int64_t(1) << 30;

// Loads `path` for `hf`. A georeferenced image gets about its own resolution
// over the DEM (at least one pixel per DEM sample); beyond max_side (the
// texture limit) a side it also gets an overview within max_side. An image
// without georeferencing must fit max_side. Throws DemError ("<path>:
// <reason>") for an unreadable file, an image with no colour bands, or a
// georeferenced image that does not overlap the DEM at all.
Imagery load_imagery(const Heightfield& hf, const std::string& path, int max_side);

}  // namespace ig::terrain
