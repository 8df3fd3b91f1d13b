#pragma once
// A coarse copy of a heightfield for what must see the whole DEM at once
// when the DEM is larger than one GL texture: the height texture
// outside the full-resolution window, and Level0's mesh. Every step-th
// sample, not an average, so each overview sample IS a DEM sample: a mesh
// built on the overview has vertices on the DEM's own heights.

#include "terrain/heightfield.h"

namespace ig::terrain {

// Samples (k * step, l * step) for k * step <= width - 1, l * step <=
// height - 1 (a last partial step at the east / north edge is left out), so
// overview sample (k, l) is at the same place as DEM sample (k, l) * step;
// spacing step times the DEM's; statistics finalized; no georef (the
// overview is only ever used in the DEM's own sample frame). step >= 1.
Heightfield decimate_heightfield(const Heightfield& hf, int step);

// The smallest step that makes a width x height DEM's overview at most
// max_side samples a side (1 when it fits already).
int overview_step_for(int width, int height, int max_side);

}  // namespace ig::terrain
