#pragma once
// The paged load of a GDAL DEM whose float heights exceed the memory budget
// (docs/terrain-data.md "Paged heights"). One pass over the
// source in strips of one tile row (page_tile rows, full width) computes
// what stays resident: the statistics, the overview (every step-th sample,
// step the smallest that makes it at most 4097 a side) and the compact
// min/max pyramid; the heights themselves are then read on demand through a
// HeightTileCache of at most the budget. Internal to ig_terrain (called by
// load_dem).

#include <cstddef>
#include <string>

#include "terrain/gdal_tile_reader.h"
#include "terrain/heightfield.h"

namespace ig::terrain {

// Side the paged overview is made to fit (render::TerrainScene::kOverviewSide).
constexpr int kPagedOverviewSide = 4097;

// Fills width, height, paged, the statistics, nodata_count and
// deep_void_count of a Heightfield for `path` (georeferencing is the
// caller's); voids filled with `void_fill` (terrain/void_fill.h). Throws
// std::runtime_error with a reason on a read failure or an all-void DEM.
Heightfield load_paged_heights(const std::string& path, const SampleDecoding& decoding,
                               const VoidFillOptions& void_fill, std::size_t budget_bytes, int tile);

}  // namespace ig::terrain
