#pragma once
// The water's waves as slopes, generated at load (no GL, nothing
// downloaded, the same bytes every run), and where they are at a time.
//
// One tileable texture of a sea surface's slopes: a sum of sinusoids with
// whole numbers of waves per tile (so it repeats seamlessly), travelling
// within 60 degrees of the wind, height amplitudes falling with wavenumber
// as a wind sea's do. Each texel holds the slope along x and y and their
// squares, so a filtered (mipmapped) read gives a footprint's mean slope and,
// from E[s^2] - E[s]^2, the slope variance its waves hide: far water turns
// smooth and its sun glint widens by exactly the roughness it lost (LEAN
// mapping's idea), so it never sparkles.
//
// The shader reads it at two tile sizes; each layer drifts down the wind at
// the phase speed of its dominant waves (deep water: c = sqrt(g L / 2 pi)).
// Slopes are dimensionless, so a layer's waves scale with its tile. The
// slope variance the texture does not resolve, and the total, follow Cox and
// Munk (1954): mean square slope 0.003 + 5.12e-3 per m/s of wind, here
// kWindMs, half of it along each axis.

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace ig::water {

struct WaveSlopes {
  int size = 0;             // texels a side (a power of two)
  std::vector<float> rgba;  // size * size * 4: slope x, slope y, slope x^2, slope y^2
};

inline constexpr double kWindMs = 5.0;
// Each texture layer's slope variance along an axis, and what no layer
// resolves (added in the shader): together Cox-Munk's half mean square slope.
inline constexpr double kSeaSlopeVariance = (0.003 + 5.12e-3 * kWindMs) / 2.0;
inline constexpr double kLayerSlopeVariance = 0.004;
inline constexpr double kUnresolvedSlopeVariance = kSeaSlopeVariance - 2.0 * kLayerSlopeVariance;

// size: a power of two >= 16.
WaveSlopes make_wave_slopes(int size = 256, std::uint32_t seed = 0x5ea5u);

struct WaveLayer {
  double tile_m;         // metres a texture repeat
  glm::dvec2 velocity;   // m/s, down the wind
};
// The two layers: a long swell-like pattern and a short chop, drifting at
// their dominant waves' phase speeds in directions 25 degrees apart.
WaveLayer wave_layer(int k);
inline constexpr int kWaveLayers = 2;

// Where whole sample `anchor` falls in layer k's tile at time t (s), in
// [0, 1) per axis, in double (as terrain::detail_tile_phase): the shader
// adds (s - anchor) * spacing / tile.
glm::dvec2 wave_phase(const glm::dvec2& anchor, const glm::dvec2& spacing_m, int k, double t_s);

}  // namespace ig::water
