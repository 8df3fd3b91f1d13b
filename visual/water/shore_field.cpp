#include "water/shore_field.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace ig::water {
namespace {

constexpr int kTaps = 2 * kShoreRadius + 1;

// The blur's weights, summing to 1.
const std::array<double, kTaps>& weights() {
  static const std::array<double, kTaps> w = [] {
    std::array<double, kTaps> v{};
    double sum = 0.0;
    for (int k = -kShoreRadius; k <= kShoreRadius; ++k) sum += v[k + kShoreRadius] = std::exp(-k * k / (2.0 * kShoreSigma * kShoreSigma));
    for (double& x : v) x /= sum;
    return v;
  }();
  return w;
}

// The sum of the weights in the order a blurred row adds them: a row that is
// water across the blur's reach gets exactly this.
double full_row_sum() {
  double acc = 0.0;
  for (double w : weights()) acc += w;
  return acc;
}

// Whether samples [a, b] of row r are all land (0), all water (1) or both (2).
int row_class(const WaterMap& map, int r, int a, int b) {
  const auto runs = map.row(r);
  const auto it = std::upper_bound(runs.begin(), runs.end(), a, [](int x, const WaterRun& run) { return x < run.end; });
  if (it == runs.end() || it->begin > b) return 0;
  if (it->begin <= a && it->end > b) return 1;
  return 2;
}

}  // namespace

std::uint8_t shore_byte(double share) { return std::uint8_t(std::lround(std::clamp(share, 0.0, 1.0) * 255.0)); }

float shore_from_byte(std::uint8_t byte) { return float(byte) / 255.0f; }

ShoreGrid shore_grid(const WaterMap& map, int step) {
  if (step < 1) throw std::invalid_argument("shore_grid: step must be >= 1");
  return {(map.width() - 1) / step + 1, (map.height() - 1) / step + 1, step};
}

void for_each_shore_row(const WaterMap& map, int step,
                        const std::function<void(int j, const std::uint8_t* share, const std::uint8_t* mask)>& row) {
  if (map.width() < 1 || map.height() < 1) return;
  const ShoreGrid g = shore_grid(map, step);
  const int w = g.width;
  const auto& wt = weights();
  // Each grid row's mask and its horizontal blur, for the rows within reach.
  std::vector<std::vector<std::uint8_t>> masks(kTaps, std::vector<std::uint8_t>(w));
  std::vector<std::vector<double>> blurred(kTaps, std::vector<double>(w));
  std::vector<std::uint8_t> full(std::size_t(map.width()));
  auto load = [&](int J, int slot) {
    map.fill_row_mask(J * step, full.data());
    std::vector<std::uint8_t>& m = masks[slot];
    for (int I = 0; I < w; ++I) m[I] = full[std::size_t(I) * step];
    for (int I = 0; I < w; ++I) {
      double acc = 0.0;
      for (int k = -kShoreRadius; k <= kShoreRadius; ++k) acc += wt[k + kShoreRadius] * m[std::clamp(I + k, 0, w - 1)];
      blurred[slot][I] = acc;
    }
  };
  auto slot_of = [](int J) { return ((J % kTaps) + kTaps) % kTaps; };
  for (int J = 0; J < std::min(kShoreRadius, g.height); ++J) load(J, slot_of(J));
  std::vector<std::uint8_t> share(w), mask(w);
  for (int J = 0; J < g.height; ++J) {
    if (J + kShoreRadius < g.height) load(J + kShoreRadius, slot_of(J + kShoreRadius));
    for (int I = 0; I < w; ++I) {
      double acc = 0.0;
      for (int l = -kShoreRadius; l <= kShoreRadius; ++l)
        acc += wt[l + kShoreRadius] * blurred[slot_of(std::clamp(J + l, 0, g.height - 1))][I];
      share[I] = shore_byte(acc);
      mask[I] = masks[slot_of(J)][I] ? 255 : 0;
    }
    row(J, share.data(), mask.data());
  }
}

double shore_share_at_sample(const WaterMap& map, int i, int j) {
  const auto& wt = weights();
  const int w = map.width(), h = map.height();
  const int a = std::max(0, i - kShoreRadius), b = std::min(w - 1, i + kShoreRadius);
  double acc = 0.0;
  for (int l = -kShoreRadius; l <= kShoreRadius; ++l) {
    const int r = std::clamp(j + l, 0, h - 1);
    // A row all one kind within reach sums as the loop would, without it.
    const int kind = row_class(map, r, a, b);
    double row = 0.0;
    if (kind == 1) {
      row = full_row_sum();
    } else if (kind == 2) {
      for (int k = -kShoreRadius; k <= kShoreRadius; ++k)
        row += wt[k + kShoreRadius] * (map.is_water(std::clamp(i + k, 0, w - 1), r) ? 1.0 : 0.0);
    }
    acc += wt[l + kShoreRadius] * row;
  }
  return acc;
}

std::optional<ShorePoint> shore_at(const WaterMap& map, double si, double sj) {
  const int w = map.width(), h = map.height();
  if (!(si >= 0.0 && sj >= 0.0 && si <= w - 1 && sj <= h - 1)) return std::nullopt;
  const int i0 = std::min(int(si), std::max(w - 2, 0)), j0 = std::min(int(sj), std::max(h - 2, 0));
  const int i1 = std::min(i0 + 1, w - 1), j1 = std::min(j0 + 1, h - 1);
  const double fx = si - i0, fy = sj - j0;
  const double s00 = shore_from_byte(shore_byte(shore_share_at_sample(map, i0, j0)));
  const double s10 = shore_from_byte(shore_byte(shore_share_at_sample(map, i1, j0)));
  const double s01 = shore_from_byte(shore_byte(shore_share_at_sample(map, i0, j1)));
  const double s11 = shore_from_byte(shore_byte(shore_share_at_sample(map, i1, j1)));
  ShorePoint p;
  p.share = float((1 - fy) * ((1 - fx) * s00 + fx * s10) + fy * ((1 - fx) * s01 + fx * s11));
  if (p.water()) {
    // The body of the nearest water sample (within the blur's reach).
    double best = std::numeric_limits<double>::max();
    for (int r = std::max(0, j0 - kShoreRadius); r <= std::min(h - 1, j1 + kShoreRadius); ++r)
      for (int c = std::max(0, i0 - kShoreRadius); c <= std::min(w - 1, i1 + kShoreRadius); ++c) {
        const double d = (c - si) * (c - si) + (r - sj) * (r - sj);
        if (d < best)
          if (const auto body = map.body_at(c, r)) {
            best = d;
            p.body = body;
          }
      }
  }
  return p;
}

}  // namespace ig::water
