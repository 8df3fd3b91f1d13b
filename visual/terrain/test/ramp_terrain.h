#pragma once
// A small geographic test terrain: 65 x 65 samples 30 m apart from 37 N,
// 118 W (or no georeference), rising 3 m a sample east with a ripple.

#include "terrain/georef.h"
#include "terrain/heightfield.h"

namespace ig::terrain::test {

inline Heightfield make_ramp_terrain(bool geographic = true) {
  Heightfield hf;
  hf.width = hf.height = 65;
  hf.spacing_x_m = hf.spacing_y_m = 30.0;
  hf.heights.resize(std::size_t(hf.width) * hf.height);
  for (int j = 0; j < hf.height; ++j)
    for (int i = 0; i < hf.width; ++i) hf.ref(i, j) = float(100.0 + 3.0 * i + 0.5 * ((i * 7 + j * 13) % 11));
  hf.finalize_stats();
  if (geographic) hf.georef = make_geographic_georef(37.0, -118.0, 30.0, 30.0);
  return hf;
}

}  // namespace ig::terrain::test
