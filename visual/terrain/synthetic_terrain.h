#pragma once
// Deterministic synthetic mountains for tests, benchmarks and demos.
//
// A seeded fractal: gradient noise from an integer hash (no std::rand, no
// <random> distributions, no threads), summed as fBm and as a ridged
// multifractal, blended by ridge_weight, tilted by a gentle large-scale
// slope, then normalised so the heights span exactly
// [base_m, base_m + relief_m]. Low ground is flattened a little (broad
// valley floors, sharp crests). Only +, -, *, / and floor are used per
// sample, in a fixed order, so a given seed gives bit-identical heights on
// every run. Feature sizes are relative to the map (the first octave has 3
// cycles per map side, and a smoother 1.6-cycle field decides where the
// ranges and the basins are), so a smaller size is the same landscape at a
// coarser resolution, not a smaller piece of it.

#include <stdexcept>

#include "options/terrain_options.h"
#include "terrain/heightfield.h"

namespace ig::terrain {

// Throws std::invalid_argument (naming the bad value) for invalid params.
// The result has no georef; source = "synthetic(seed=S,size=N)".
Heightfield generate_synthetic_terrain(const options::SyntheticTerrainOptions& params);

}  // namespace ig::terrain
