#pragma once
// Nodata (void) filling shared by the whole-array DEM load and the paged
// tile reader (docs/terrain-data.md "Nodata"): GDAL's own algorithm,
// GDALFillNodata (the engine of gdal_fillnodata.py), then a layer fill for
// the deep voids it leaves.

#include <climits>
#include <cstdint>
#include <vector>

#include "options/terrain_options.h"

namespace ig::terrain {

using VoidFillOptions = options::VoidFillOptions;

struct VoidFillResult {
  std::int64_t voids = 0;  // void samples in the grid
  std::int64_t deep = 0;   // of those, with no valid sample within max_distance (filled by layers)
};

// Fills the void samples (valid[k] == 0; valid ones non-zero) of a w x ht
// grid h, rows south first, as `gdal_fillnodata.py -md D -si S` fills the
// file (D = opts.max_distance, S = opts.smoothing_iterations): each void
// sample takes the inverse-distance mean of the nearest valid sample in each
// of four quadrants within D samples, then S 3x3 mean passes smooth the
// filled samples. GDALFillNodata runs over in-memory (MEM) datasets wrapping
// h and a mask, no temporary files, on the rows in the file's order (north
// first): its search treats the rows above a sample and those below it
// differently, so only that order gives the tool's values.
//
// Deep voids, the samples GDAL leaves (no valid sample within D in any
// quadrant), are then filled inward layer by layer: each takes the mean of
// its already-filled 8-neighbours, so they meet the GDAL-filled rim without a
// step. A deep sample's layer is its distance in 8-neighbour steps to the
// nearest sample that is valid or GDAL-filled. With `deep_layers` (resized
// to w * ht) every sample gets its layer: 0 for all but deep voids,
// kUnfilledLayer where the grid has no valid sample at all (those are left
// NaN). Throws std::runtime_error when GDAL fails (memory) and
// std::invalid_argument for settings out of range.
constexpr std::int32_t kUnfilledLayer = INT32_MAX;
VoidFillResult fill_voids(std::vector<float>& h, const std::vector<std::uint8_t>& valid, int w, int ht,
                          const VoidFillOptions& opts, std::vector<std::int32_t>* deep_layers = nullptr);

}  // namespace ig::terrain
