#pragma once
// The level a mapped water body lies at, and the heights under it made level.
// No GL.
//
// A body read from the user's water data (polygons or a mask) has no level
// of its own unless an attribute gives one. It is taken from the DEM:
//  * SWBD-edited data (SRTM): most of the body is one exact height, the
//    flattened surface; when one height holds at least half its samples,
//    that height;
//  * otherwise (a DEM with the water surface unedited, or with the bed
//    under it): the median height of its rim, the water samples next to
//    land, since water stands as high as its shore;
//  * within 1 m of 0 m: 0 m, the sea (a coastal rim's heights scatter
//    around it).
// Then every water sample of heights held whole is set to its body's level,
// so the surface every method draws, and the host queries answer, is the
// water's (flatten_to_levels). The levels and flattening read and write
// the grid row by row (water/height_rows.h).

#include <cstdint>

#include "terrain/heightfield.h"
#include "water/water_map.h"

namespace ig::water {

inline constexpr float kSeaSnapM = 1.0f;

// Sets the level of every body of `map` (the DEM's samples under it) as above.
void choose_levels(WaterMap& map, const terrain::Heightfield& hf);

// Sets every water sample of hf (heights held whole) to its body's level and
// refreshes hf's statistics; returns how many samples changed. Paged heights
// are left as they are (returns 0): their overview and pyramid were built
// from the file in the one load pass.
std::int64_t flatten_to_levels(terrain::Heightfield& hf, const WaterMap& map);

}  // namespace ig::water
