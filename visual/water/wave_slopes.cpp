#include "water/wave_slopes.h"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include <glm/common.hpp>

namespace ig::water {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kGravity = 9.81;
constexpr double kWindDeg = 20.0;       // the texture's waves travel this far north of east
constexpr double kSecondLayerDeg = 25.0;  // the chop's drift, turned from the swell's
constexpr double kTileM[kWaveLayers] = {61.7, 17.3};

struct Component {
  double n, m;     // waves per tile along x, y
  double amplitude;
  double phase;
};

}  // namespace

WaveSlopes make_wave_slopes(int size, std::uint32_t seed) {
  if (size < 16 || (size & (size - 1)) != 0) throw std::invalid_argument("make_wave_slopes: size must be a power of two >= 16");
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double wind = kWindDeg * kPi / 180.0;
  std::vector<Component> waves;
  double variance = 0.0;  // of the slope, x and y together, before scaling
  for (int m = -16; m <= 16; ++m)
    for (int n = -16; n <= 16; ++n) {
      const double k = std::hypot(double(n), double(m));
      if (k < 2.0 || k > 16.0) continue;
      const double off = std::remainder(std::atan2(double(m), double(n)) - wind, 2.0 * kPi);
      if (std::fabs(off) > kPi / 3.0) continue;  // within 60 degrees of the wind
      if (uniform(rng) > 0.45) continue;          // a sparse spectrum: no grid of crests
      const double spread = std::cos(off) * std::cos(off);
      Component c{double(n), double(m), spread / (k * k), 2.0 * kPi * uniform(rng)};
      waves.push_back(c);
      variance += 0.5 * std::pow(2.0 * kPi * c.amplitude, 2) * k * k;
    }
  const double scale = std::sqrt(2.0 * kLayerSlopeVariance / variance);
  WaveSlopes out;
  out.size = size;
  out.rgba.resize(std::size_t(size) * size * 4);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double u = (x + 0.5) / size, v = (y + 0.5) / size;
      double sx = 0.0, sy = 0.0;
      for (const Component& c : waves) {
        const double s = -2.0 * kPi * c.amplitude * scale * std::sin(2.0 * kPi * (c.n * u + c.m * v) + c.phase);
        sx += s * c.n;
        sy += s * c.m;
      }
      float* t = &out.rgba[(std::size_t(y) * size + x) * 4];
      t[0] = float(sx);
      t[1] = float(sy);
      t[2] = float(sx * sx);
      t[3] = float(sy * sy);
    }
  return out;
}

WaveLayer wave_layer(int k) {
  if (k < 0 || k >= kWaveLayers) throw std::out_of_range("wave_layer: no such layer");
  // The dominant waves are about a fifth of the tile long.
  const double dominant_m = kTileM[k] / 5.0;
  const double speed = std::sqrt(kGravity * dominant_m / (2.0 * kPi));
  const double angle = (kWindDeg + (k == 1 ? kSecondLayerDeg : 0.0)) * kPi / 180.0;
  return {kTileM[k], glm::dvec2(std::cos(angle), std::sin(angle)) * speed};
}

glm::dvec2 wave_phase(const glm::dvec2& anchor, const glm::dvec2& spacing_m, int k, double t_s) {
  const WaveLayer layer = wave_layer(k);
  // The pattern drifts with the layer: at time t the surface at x shows what
  // was at x - v t.
  const glm::dvec2 at = (anchor * spacing_m - layer.velocity * t_s) / layer.tile_m;
  return at - glm::floor(at);
}

}  // namespace ig::water
