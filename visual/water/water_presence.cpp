#include "water/water_presence.h"

#include <algorithm>
#include <cmath>


namespace ig::water {
namespace {

int power_of_two_at_least(int n) {
  int p = 1;
  while (p < n) p *= 2;
  return p;
}

// A level's mean shares as bytes, rounded to the nearest.
PresenceLevel quantised(int width, int height, const std::vector<double>& mean) {
  PresenceLevel out{width, height, std::vector<std::uint8_t>(mean.size())};
  for (std::size_t k = 0; k < mean.size(); ++k) out.texels[k] = std::uint8_t(std::lround(std::clamp(mean[k], 0.0, 1.0) * 255.0));
  return out;
}

}  // namespace

PresenceBuilder::PresenceBuilder(const ShoreGrid& grid)
    : grid_(grid),
      width_(power_of_two_at_least((grid.width + kPresenceBlock - 1) / kPresenceBlock)),
      height_(power_of_two_at_least((grid.height + kPresenceBlock - 1) / kPresenceBlock)),
      mean_(std::size_t(width_) * std::size_t(height_), 0.0) {}

void PresenceBuilder::add_row(int j, const std::uint8_t* share) {
  const double per_texel = 1.0 / (255.0 * kPresenceBlock * kPresenceBlock);
  double* row = mean_.data() + std::size_t(j / kPresenceBlock) * width_;
  for (int i = 0; i < grid_.width; ++i) row[i / kPresenceBlock] += share[i] * per_texel;
}

std::vector<PresenceLevel> PresenceBuilder::levels() const {
  int w = width_, h = height_;
  std::vector<double> mean = mean_;
  std::vector<PresenceLevel> levels{quantised(w, h, mean)};
  while (w > 1 || h > 1) {
    const int nw = std::max(w / 2, 1), nh = std::max(h / 2, 1);
    std::vector<double> next(std::size_t(nw) * nh, 0.0);
    const double part = 1.0 / double((w / nw) * (h / nh));
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) next[std::size_t(y / (h / nh)) * nw + x / (w / nw)] += mean[std::size_t(y) * w + x] * part;
    mean = std::move(next);
    w = nw;
    h = nh;
    levels.push_back(quantised(w, h, mean));
  }
  return levels;
}

std::vector<PresenceLevel> water_presence(const WaterMap& map, int step) {
  PresenceBuilder builder(shore_grid(map, step));
  for_each_shore_row(map, step, [&](int j, const std::uint8_t* share, const std::uint8_t*) { builder.add_row(j, share); });
  return builder.levels();
}

}  // namespace ig::water
