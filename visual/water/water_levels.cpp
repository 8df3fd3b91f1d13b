#include "water/water_levels.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "water/height_rows.h"

namespace ig::water {
namespace {

constexpr std::uint32_t kLand = ~std::uint32_t(0);

// Row j of the map as body indices (kLand for land); empty rows outside.
void body_row(const WaterMap& map, int j, std::vector<std::uint32_t>& out) {
  std::fill(out.begin(), out.end(), kLand);
  if (j < 0 || j >= map.height()) return;
  for (const WaterRun& r : map.row(j)) std::fill(out.begin() + r.begin, out.begin() + r.end, r.body);
}

}  // namespace

void choose_levels(WaterMap& map, const terrain::Heightfield& hf) {
  auto& bodies = map.bodies();
  const int w = map.width();
  // Pass 1: each body's majority candidate (Boyer-Moore: the one height
  // that can hold more than half of it) and its rim's heights.
  std::vector<float> candidate(bodies.size(), 0.0f);
  std::vector<std::int64_t> votes(bodies.size(), 0);
  std::vector<std::vector<float>> rim(bodies.size());
  std::vector<std::uint32_t> below(w), here(w), above(w);
  HeightRows rows(hf);
  body_row(map, -1, below);
  body_row(map, 0, here);
  for (int j = 0; j < map.height(); ++j) {
    body_row(map, j + 1, above);
    const float* h = rows.row(j);
    for (int i = 0; i < w; ++i) {
      const std::uint32_t b = here[i];
      if (b == kLand) continue;
      if (votes[b] == 0) {
        candidate[b] = h[i];
        votes[b] = 1;
      } else {
        votes[b] += candidate[b] == h[i] ? 1 : -1;
      }
      const bool shore = (i > 0 && here[i - 1] == kLand) || (i + 1 < w && here[i + 1] == kLand) ||
                         (j > 0 && below[i] == kLand) || (j + 1 < map.height() && above[i] == kLand);
      if (shore) rim[b].push_back(h[i]);
    }
    std::swap(below, here);
    std::swap(here, above);
  }
  // Pass 2: how many samples the candidate really holds.
  std::vector<std::int64_t> held(bodies.size(), 0);
  for (int j = 0; j < map.height(); ++j) {
    const float* h = rows.row(j);
    for (const WaterRun& r : map.row(j))
      for (int i = r.begin; i < r.end; ++i) held[r.body] += h[i] == candidate[r.body];
  }
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    float level = candidate[b];
    if (2 * held[b] < bodies[b].samples && !rim[b].empty()) {
      auto mid = rim[b].begin() + std::ptrdiff_t(rim[b].size() / 2);
      std::nth_element(rim[b].begin(), mid, rim[b].end());
      level = *mid;
    }
    if (std::fabs(level) <= kSeaSnapM) level = 0.0f;
    bodies[b].level_m = level;
  }
}

std::int64_t flatten_to_levels(terrain::Heightfield& hf, const WaterMap& map) {
  if (!hf.has_whole_heights() || map.width() != hf.width || map.height() != hf.height) return 0;
  std::int64_t changed = 0;
  for (int j = 0; j < hf.height; ++j)
    for (const WaterRun& r : map.row(j)) {
      const float level = map.bodies()[r.body].level_m;
      for (int i = r.begin; i < r.end; ++i) {
        float& h = hf.ref(i, j);
        changed += h != level;
        h = level;
      }
    }
  if (changed > 0) hf.finalize_stats();
  return changed;
}

}  // namespace ig::water
