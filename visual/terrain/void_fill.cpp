#include "terrain/void_fill.h"

#include <algorithm>

namespace ig::terrain {

std::int64_t fill_voids(std::vector<float>& h, std::vector<std::uint8_t>& state, int w, int ht,
                        std::vector<std::int32_t>* layers) {
  // state: 0 void, 1 valid, 2 void already queued.
  std::int64_t voids = 0;
  for (std::uint8_t s : state) voids += (s == 0);
  if (layers) {
    layers->assign(state.size(), 0);
    for (std::size_t k = 0; k < state.size(); ++k)
      if (state[k] == 0) (*layers)[k] = kUnfilledLayer;
  }
  if (voids == 0) return 0;

  auto for_neighbours = [&](std::uint32_t k, auto&& fn) {
    const int i = int(k % std::uint32_t(w)), j = int(k / std::uint32_t(w));
    for (int dj = -1; dj <= 1; ++dj) {
      const int jj = j + dj;
      if (jj < 0 || jj >= ht) continue;
      for (int di = -1; di <= 1; ++di) {
        const int ii = i + di;
        if ((di == 0 && dj == 0) || ii < 0 || ii >= w) continue;
        fn(std::uint32_t(jj) * std::uint32_t(w) + std::uint32_t(ii));
      }
    }
  };

  std::vector<std::uint32_t> frontier, next;
  for (std::uint32_t k = 0; k < state.size(); ++k) {
    if (state[k] != 0) continue;
    bool near_valid = false;
    for_neighbours(k, [&](std::uint32_t n) { near_valid |= (state[n] == 1); });
    if (near_valid) {
      state[k] = 2;
      frontier.push_back(k);
    }
  }
  std::vector<float> values;
  for (std::int32_t layer = 1; !frontier.empty(); ++layer) {
    values.resize(frontier.size());
    for (std::size_t f = 0; f < frontier.size(); ++f) {
      double sum = 0.0;
      int count = 0;
      for_neighbours(frontier[f], [&](std::uint32_t n) {
        if (state[n] == 1) {
          sum += h[n];
          ++count;
        }
      });
      values[f] = float(sum / std::max(count, 1));
    }
    next.clear();
    for (std::size_t f = 0; f < frontier.size(); ++f) {
      h[frontier[f]] = values[f];
      state[frontier[f]] = 1;
      if (layers) (*layers)[frontier[f]] = layer;
    }
    for (std::uint32_t k : frontier)
      for_neighbours(k, [&](std::uint32_t n) {
        if (state[n] == 0) {
          state[n] = 2;
          next.push_back(n);
        }
      });
    frontier.swap(next);
  }
  return voids;
}

}  // namespace ig::terrain
