#pragma once
// Terrain for the water tests: rough integer land (no two neighbours alike
// but by chance) with the water an SRTM edit leaves and the traps beside it,
// 90 m apart, georeferenced like test_geotiff.h (EPSG:4326 from 119 W, 37.5 N).

#include <cmath>
#include <cstdint>
#include <vector>

#include "terrain/georef.h"
#include "terrain/heightfield.h"

namespace ig::water::test {

// Samples of each feature (south-up (i, j)).
struct TestFeatures {
  int sea_rows = 12;                                // rows 0 .. sea_rows - 1: the sea at exactly 0 m
  int terrace_rows = 48;                            // then a plain rising from the sea in 1 m terraces 8 rows deep
  int lake_i = 60, lake_j = 95, lake_r = 12;        // a lake at exactly kLakeLevel, land rising around it
  int pond_i = 150, pond_j = 140;                   // a flat 3 x 3 pond: below the minimum size
  int playa_i = 30, playa_j = 125, playa_r = 8;     // a closed flat at kPlayaLevel, its rim 1 m higher
  int below_i = 195, below_j = 100, below_r = 14;   // dry land below sea level inside a 3-sample ring at exactly
                                                    // 0 m, cut by the east edge (the north of Death Valley)
};
inline constexpr float kLakeLevel = 1200.0f;
inline constexpr float kPlayaLevel = 900.0f;

// Rough land: integers 1300..1359 from a hash, so flat 2 x 2 blocks are rare.
inline float rough(int i, int j) {
  std::uint32_t x = std::uint32_t(i) * 73856093u ^ std::uint32_t(j) * 19349663u;
  x ^= x >> 13;
  x *= 0x5bd1e995u;
  x ^= x >> 15;
  return 1300.0f + float(x % 60u);
}

inline terrain::Heightfield make_water_test_terrain(int w = 200, int h = 150, const TestFeatures& f = {}) {
  terrain::Heightfield hf;
  hf.width = w;
  hf.height = h;
  hf.spacing_x_m = hf.spacing_y_m = 90.0;
  hf.heights.resize(std::size_t(w) * h);
  auto inside = [](int i, int j, int ci, int cj, int r) { return (i - ci) * (i - ci) + (j - cj) * (j - cj) <= r * r; };
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      float v = rough(i, j);
      if (inside(i, j, f.lake_i, f.lake_j, f.lake_r)) v = kLakeLevel;
      if (i >= f.pond_i && i < f.pond_i + 3 && j >= f.pond_j && j < f.pond_j + 3) v = 1250.0f;
      if (j >= f.sea_rows && j < f.sea_rows + f.terrace_rows) v = 100.0f + float((j - f.sea_rows) / 8);
      if (inside(i, j, f.playa_i, f.playa_j, f.playa_r + 2)) v = kPlayaLevel + 1.0f;
      if (inside(i, j, f.playa_i, f.playa_j, f.playa_r)) v = kPlayaLevel;
      if (inside(i, j, f.below_i, f.below_j, f.below_r + 3)) v = 0.0f;
      if (inside(i, j, f.below_i, f.below_j, f.below_r)) v = -1.0f - float((i + j) % 40);
      if (j < f.sea_rows) v = 0.0f;
      hf.ref(i, j) = v;
    }
  hf.finalize_stats();
  hf.georef = terrain::make_geographic_georef(37.5 - (h - 1) / 1200.0, -119.0, 90.0, 90.0);
  hf.source = "water test terrain";
  return hf;
}

}  // namespace ig::water::test
