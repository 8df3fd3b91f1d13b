#pragma once
// Small test terrains shared by the LOD tests (unit and GL): a heightfield
// from a formula (bumps, planes), a synthetic landscape, the south-west
// corner of one cropped to any size, and a set of those of many sizes.
#include <algorithm>
#include <functional>
#include <vector>

#include "terrain/heightfield.h"
#include "terrain/synthetic_terrain.h"

namespace lod_checks {

// A w x h heightfield at the given spacing with heights height(i, j).
inline ig::terrain::Heightfield heightfield_from(int w, int h, double spacing_x_m, double spacing_y_m,
                                                 const std::function<double(int, int)>& height) {
  ig::terrain::Heightfield hf;
  hf.width = w;
  hf.height = h;
  hf.spacing_x_m = spacing_x_m;
  hf.spacing_y_m = spacing_y_m;
  hf.heights.resize(size_t(w) * h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) hf.ref(i, j) = float(height(i, j));
  hf.finalize_stats();
  return hf;
}

inline ig::terrain::Heightfield synthetic(int size, unsigned seed = 3, double spacing = 30.0) {
  ig::options::SyntheticTerrainOptions p;
  p.size = size;
  p.seed = seed;
  p.spacing_m = spacing;
  return ig::terrain::generate_synthetic_terrain(p);
}

// The south-west w x h samples of a synthetic terrain (any size).
inline ig::terrain::Heightfield cropped(int w, int h, unsigned seed = 5) {
  int n = 3;
  while (n < std::max(w, h)) n = 2 * n - 1;
  const auto full = synthetic(n, seed);
  return heightfield_from(w, h, full.spacing_x_m, full.spacing_y_m, [&](int i, int j) { return full.at(i, j); });
}

// A 65^2 landscape and crops of it: odd, non-square, thin and tiny.
inline std::vector<ig::terrain::Heightfield> dems_of_many_sizes() {
  return {synthetic(65), cropped(70, 37), cropped(33, 100), cropped(2, 2), cropped(3, 6)};
}

}  // namespace lod_checks
