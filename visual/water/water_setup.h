#pragma once
// The water a terrain's settings ask for (terrain.water), found or read and
// placed on its heightfield: the one entry point the session and ig info
// use. No GL.

#include <memory>

#include "options/water_options.h"
#include "terrain/heightfield.h"
#include "water/water_map.h"

namespace ig::water {

// Auto: the water found in the DEM (water/water_detection.h). File: the
// user's water data (water/water_file.h), its samples made level where the
// heights are held whole (water/water_levels.h). Off: none (nullptr).
// hf.water is set when the map has a body, so a scene without water has
// none to draw. Throws WaterFileError for a bad file.
std::shared_ptr<const WaterMap> place_water(terrain::Heightfield& hf, const options::WaterOptions& opts);

}  // namespace ig::water
