#pragma once
// What a paged Heightfield keeps resident (terrain beyond a memory
// budget; docs/terrain-data.md "Paged heights"): the tile cache the
// samples are read through, and what the loader built in its one pass over
// the source: the overview (every overview_step-th sample, the scene's
// height texture and Level0's grid) and the compact min/max pyramid (ray
// casts, host queries, culling bounds). No GL.

#include <cstdint>
#include <memory>

#include "terrain/height_pyramid.h"
#include "terrain/height_tile_cache.h"
#include "terrain/heightfield.h"

namespace ig::terrain {

struct PagedHeights {
  std::shared_ptr<HeightTileCache> cache;
  std::shared_ptr<const Heightfield> overview;
  int overview_step = 1;
  std::shared_ptr<const HeightPyramid> pyramid;
  // Deep void samples filled from a bounded neighbourhood that may differ
  // from the whole-array load's fill: more than kMaxExactDeepLayer layers
  // inside GDAL's reach (terrain/gdal_tile_reader.h). 0 for most DEMs.
  std::int64_t inexact_voids = 0;
  // What the source needs while tiles are read (a folder's in-memory mosaic
  // VRTs, terrain/dem_mosaic.h); empty for a file.
  std::shared_ptr<const void> source_keep_alive;
};

}  // namespace ig::terrain
