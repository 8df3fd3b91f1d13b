#pragma once
// What the water picture tests measure: where water is drawn (the pixels a
// render with water and one without differ in) and the error along the
// shore against a 4 x 4-supersampled, box-filtered render of the same view.

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "picture_checks.h"

namespace water_checks {

inline ig::io::Scenario without_water(ig::io::Scenario s) {
  s.terrain.water.source = ig::options::WaterSource::Off;
  return s;
}

// Pixels that differ between two shots of one view (water on and off).
inline std::vector<bool> differing(const picture::Shot& a, const picture::Shot& b) {
  std::vector<bool> out(std::size_t(a.w) * a.h);
  for (std::size_t p = 0; p < out.size(); ++p)
    for (int k = 0; k < 3; ++k) out[p] = out[p] || a.rgba[p * 4 + k] != b.rgba[p * 4 + k];
  return out;
}

struct ShoreError {
  double mean = 0.0;  // levels, mean of R, G, B
  long long pixels = 0;
};

// The shore: pixels whose 4 x 4 block in the supersampled render (with and
// without water, 4x the size of `shot`) holds both water and land and no
// sky. Mean |difference| of `shot` from the box-filtered render there.
inline ShoreError shore_error(const picture::Shot& shot, const picture::Shot& ss_with, const picture::Shot& ss_without) {
  const std::vector<bool> wet = differing(ss_with, ss_without);
  const picture::Shot ss = picture::box_filter(ss_with, 4);
  ShoreError e;
  double sum = 0.0;
  for (int y = 1; y + 1 < shot.h; ++y)
    for (int x = 1; x + 1 < shot.w; ++x) {
      int water = 0, sky = 0;
      for (int v = 0; v < 4; ++v)
        for (int u = 0; u < 4; ++u) {
          const std::size_t q = std::size_t(y * 4 + v) * ss_with.w + (x * 4 + u);
          water += wet[q];
          sky += ss_with.depth[q] == 0.0f;
        }
      if (water == 0 || water == 16 || sky > 0) continue;
      const std::size_t p = std::size_t(y) * shot.w + x;
      double d = 0.0;
      for (int k = 0; k < 3; ++k) d += std::abs(int(shot.rgba[p * 4 + k]) - int(ss.rgba[p * 4 + k]));
      sum += d / 3.0;
      ++e.pixels;
    }
  e.mean = e.pixels ? sum / double(e.pixels) : 0.0;
  return e;
}

}  // namespace water_checks
