#include "terrain/detail_noise.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/common.hpp>

#include "terrain/lattice_hash.h"

namespace ig::terrain {
namespace {

double lattice(int i, int j, int period, std::uint32_t seed) {
  const auto wrap = [period](int v) { return std::uint32_t(((v % period) + period) % period); };
  return double(hash3(wrap(i), wrap(j), seed)) / 4294967295.0 * 2.0 - 1.0;
}

// Value noise with a quintic fade, periodic over `period` lattice cells.
double value_noise(double x, double y, int period, std::uint32_t seed) {
  const int i = int(std::floor(x)), j = int(std::floor(y));
  const double fx = x - i, fy = y - j;
  const auto fade = [](double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); };
  const double u = fade(fx), v = fade(fy);
  const double a = lattice(i, j, period, seed), b = lattice(i + 1, j, period, seed);
  const double c = lattice(i, j + 1, period, seed), d = lattice(i + 1, j + 1, period, seed);
  return (a + (b - a) * u) * (1.0 - v) + (c + (d - c) * u) * v;
}

// Fractal sum of octaves from `cells` lattice cells across the tile, each
// octave twice as many cells at `gain` the amplitude; stays tileable.
std::vector<double> fractal(int size, int cells, int octaves, double gain, std::uint32_t seed) {
  std::vector<double> out(std::size_t(size) * size, 0.0);
  double amplitude = 1.0;
  for (int o = 0; o < octaves && cells <= size; ++o, cells *= 2, amplitude *= gain) {
    const double scale = double(cells) / size;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        out[std::size_t(y) * size + x] += amplitude * value_noise((x + 0.5) * scale, (y + 0.5) * scale, cells,
                                                                  hash3(seed, std::uint32_t(o), 0xDE7Au));
  }
  return out;
}

// To bytes with mean 127.5 and standard deviation `spread` (clamped).
void write_channel(std::vector<std::uint8_t>& rgba, int channel, const std::vector<double>& v, double spread) {
  double mean = 0.0, var = 0.0;
  for (double x : v) mean += x;
  mean /= double(v.size());
  for (double x : v) var += (x - mean) * (x - mean);
  const double sd = std::sqrt(var / double(v.size()));
  for (std::size_t k = 0; k < v.size(); ++k) {
    const double b = 127.5 + (v[k] - mean) / std::max(sd, 1e-12) * spread;
    rgba[4 * k + channel] = std::uint8_t(std::clamp(std::lround(b), 0L, 255L));
  }
}

}  // namespace

DetailNoise make_detail_noise(int size, std::uint32_t seed) {
  if (size < 64 || (size & (size - 1)) != 0)
    throw std::invalid_argument("detail noise size " + std::to_string(size) + " is not a power of two >= 64");
  DetailNoise n;
  n.size = size;
  n.rgba.assign(std::size_t(size) * size * 4, 0);
  constexpr double kSpread = 40.0;  // bytes: 3.2 standard deviations to either end, few texels clamp
  write_channel(n.rgba, 0, fractal(size, size / 2, 2, 0.6, seed + 1), kSpread);
  write_channel(n.rgba, 1, fractal(size, 32, 3, 0.55, seed + 2), kSpread);
  write_channel(n.rgba, 2, fractal(size, 8, 4, 0.55, seed + 3), kSpread);
  write_channel(n.rgba, 3, fractal(size, 2, 3, 0.5, seed + 4), kSpread);
  return n;
}

glm::dvec2 detail_tile_phase(const glm::dvec2& anchor, const glm::dvec2& spacing_m, double tile_m) {
  const glm::dvec2 tiles = anchor * spacing_m / tile_m;
  return tiles - glm::floor(tiles);
}

}  // namespace ig::terrain
