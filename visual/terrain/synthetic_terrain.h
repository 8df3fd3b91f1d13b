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

#include "terrain/heightfield.h"

namespace ig::terrain {

struct SyntheticTerrainParams {
  int size = 1025;           // samples per side: 2^n + 1, 3 ... 16385
  unsigned seed = 1;         // any value; different seeds give different terrain
  double spacing_m = 30;     // sample spacing (both axes), > 0
  double relief_m = 1500;    // max - min height, >= 0
  double base_m = 0;         // lowest height
  int octaves = 9;           // noise octaves, 1 ... 24
  double ridge_weight = 0.5; // 0 = rolling fBm hills, 1 = pure ridged mountains
};

// Throws std::invalid_argument (naming the bad value) for invalid params.
// The result has no georef; source = "synthetic(seed=S,size=N)".
Heightfield generate_synthetic_terrain(const SyntheticTerrainParams& params);

}  // namespace ig::terrain
