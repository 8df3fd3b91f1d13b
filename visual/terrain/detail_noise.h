#pragma once
// The ground-detail texture's texels (no GL): a tileable fractal noise
// image, generated at load (nothing downloaded, the same bytes every run).
// Four independent channels, each a different grain size so one texture
// serves every scale the shading needs (shaders/terrain_shading.frag):
//   r: fine grain     (features ~1/128 of the tile: pebbles, grass tufts)
//   g: clumps         (~1/32: shrubs, boulders)
//   b: patches        (~1/8: soil and vegetation patches)
//   a: broad swells   (~1/2: where materials give way to each other)
// Every channel has mean 0.5 (127.5 in bytes, to rounding) and the same
// spread, so a fully filtered (far, top mip) lookup is neutral and a
// distant surface fades to its mean colour instead of shifting.

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace ig::terrain {

struct DetailNoise {
  int size = 0;                    // texels a side (a power of two)
  std::vector<std::uint8_t> rgba;  // size * size * 4, row-major
};

// size: a power of two >= 64. seed: any; the same seed gives the same bytes.
DetailNoise make_detail_noise(int size = 256, std::uint32_t seed = 0x1d6e5a1u);

// Where whole sample `anchor` (terrain-local sample indices) falls in a
// detail tile `tile_m` metres wide, in tiles, in [0, 1) per axis. The shader
// adds (s - anchor) * spacing / tile_m to it: the same tile coordinate (up
// to whole tiles) whatever the anchor, computed in double here so it stays
// exact where a float product anchor * spacing / tile_m would not.
glm::dvec2 detail_tile_phase(const glm::dvec2& anchor, const glm::dvec2& spacing_m, double tile_m);

}  // namespace ig::terrain
