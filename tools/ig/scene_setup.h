#pragma once
// Turning a scenario's declarative parts into things the IG can use: the
// heightfield (file or generator) and the ownship path in terrain-local
// metres above sea level.

#include "io/scenario.h"
#include "terrain/heightfield.h"

namespace ig::app {

// Throws terrain::DemError / std::invalid_argument with a one-line reason.
terrain::Heightfield load_terrain(const io::TerrainSpec& spec);

// Keys converted to local ENU metres above sea level: geodetic keys through
// the DEM's georeference (error when it has none), AGL altitudes on top of
// the surface under each key. Throws io::ScenarioError naming the key.
io::PathSpec place_path(const io::PathSpec& path, const terrain::Heightfield& hf);

}  // namespace ig::app
