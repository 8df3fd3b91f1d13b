#pragma once
// The water's textures (shaders/water.frag): the share of water around each
// sample (R8, mipmapped: far away a texel's mips are the water's part of
// it; water/shore_field.h) and the waves' slopes (RGBA16F, tiling,
// mipmapped; water/wave_slopes.h), and where water may be (R8 levels of
// its own; water/water_presence.h).

#include <cstdint>
#include <functional>
#include <vector>

#include "gl/gl_objects.h"

namespace ig::gl {

// width x height texels, filled row by row (row 0 first): `rows` calls its
// argument with (j, width bytes) for every row.
using ShareRows = std::function<void(const std::function<void(int j, const std::uint8_t* share)>&)>;
Texture upload_water_share_texture(int width, int height, const ShareRows& rows);
// size x size texels of four floats each.
Texture upload_wave_texture(int size, const float* rgba);
// Where water may be (water/water_presence.h): R8, one texture level per
// level given (each half the one before), read bilinearly within a level.
struct PresenceTexels {
  int width, height;
  const std::uint8_t* texels;
};
Texture upload_water_presence_texture(const std::vector<PresenceTexels>& levels);

}  // namespace ig::gl
