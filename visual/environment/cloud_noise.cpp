#include "environment/cloud_noise.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ig::environment {
namespace {

// A lattice value in [0, 1) for integer point (x, y) of a lattice of the
// given period (wrapped, so the field tiles).
float lattice(int x, int y, int period, std::uint32_t seed) {
  x = ((x % period) + period) % period;
  y = ((y % period) + period) % period;
  std::uint32_t h = std::uint32_t(x) * 0x8da6b343u ^ std::uint32_t(y) * 0xd8163841u ^ (seed + std::uint32_t(period)) * 0xcb1ab31fu;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return float(h & 0xffffffu) / float(0x1000000);
}

// The coarsest octave's lattice, stratified: the four points of every 2 x 2
// block take one value from each quarter of [0, 1) (in an order and with a
// jitter of their own), so no stretch of a few elements is all cloud or all
// gap, as independent values would often make it.
float stratified_lattice(int x, int y, int period, std::uint32_t seed) {
  x = ((x % period) + period) % period;
  y = ((y % period) + period) % period;
  const float block = lattice(x / 2, y / 2, period / 2, seed ^ 0x9e3779b9u);
  const int turn = int(block * 4.0f);  // which quarter the block's first point takes
  const int k = (x % 2) + 2 * (y % 2);
  const int order[4] = {0, 3, 1, 2};   // diagonal neighbours far apart
  const float jitter = lattice(x, y, period, seed ^ 0x85ebca6bu) - 0.5f;
  return (float((order[k] + turn) % 4) + 0.5f + 0.5f * jitter) / 4.0f;
}

float smooth(float t) { return t * t * (3.0f - 2.0f * t); }

// Value noise of lattice period `period` texels at texel (x, y).
float value_noise(int x, int y, int cells, int period, std::uint32_t seed, bool stratified) {
  const float fx = float(x) / float(period), fy = float(y) / float(period);
  const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  const float tx = smooth(fx - float(x0)), ty = smooth(fy - float(y0));
  auto at = [&](int x, int y) { return stratified ? stratified_lattice(x, y, cells, seed) : lattice(x, y, cells, seed); };
  const float a = at(x0, y0), b = at(x0 + 1, y0);
  const float c = at(x0, y0 + 1), d = at(x0 + 1, y0 + 1);
  return (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
}

}  // namespace

std::vector<float> cloud_noise_field(std::uint32_t seed, int side) {
  const std::size_t n = std::size_t(side) * std::size_t(side);
  std::vector<float> sum(n, 0.0f);
  float amplitude = 1.0f;
  const int coarsest = std::min(kCloudNoiseLowestPeriod, side);
  for (int period = coarsest; period >= 2; period /= 2) {
    const int cells = side / period;  // lattice points a side: the octave wraps with the field
    const bool stratified = period >= coarsest / 2 && cells % 2 == 0;  // the two coarsest octaves
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x)
        sum[std::size_t(y) * side + x] += amplitude * value_noise(x, y, cells, period, seed, stratified);
    amplitude *= 0.65f;
  }
  // Rank: the k-th smallest value becomes (k + 0.5) / n.
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return sum[a] < sum[b] || (sum[a] == sum[b] && a < b);
  });
  std::vector<float> out(n);
  for (std::size_t k = 0; k < n; ++k) out[order[k]] = (float(k) + 0.5f) / float(n);
  return out;
}

}  // namespace ig::environment
