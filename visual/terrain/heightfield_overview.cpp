#include "terrain/heightfield_overview.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace ig::terrain {

Heightfield decimate_heightfield(const Heightfield& hf, int step) {
  if (step < 1) throw std::invalid_argument("decimate_heightfield: step " + std::to_string(step) + " < 1");
  Heightfield o;
  o.width = (hf.width - 1) / step + 1;
  o.height = (hf.height - 1) / step + 1;
  o.spacing_x_m = hf.spacing_x_m * step;
  o.spacing_y_m = hf.spacing_y_m * step;
  o.heights.resize(static_cast<std::size_t>(o.width) * o.height);
  for (int l = 0; l < o.height; ++l)
    for (int k = 0; k < o.width; ++k) o.ref(k, l) = hf.at(k * step, l * step);
  o.finalize_stats();
  o.nodata_count = 0;
  o.source = hf.source + " (overview, every " + std::to_string(step) + " samples)";
  return o;
}

int overview_step_for(int width, int height, int max_side) {
  // (longest - 1) / step + 1 <= max_side  <=>  step > (longest - 1) / max_side.
  const int longest = std::max(width, height);
  return (longest - 1) / std::max(max_side, 1) + 1;
}

}  // namespace ig::terrain
