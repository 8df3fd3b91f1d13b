#pragma once
// The scene's textures: heights (R32F, one float per sample, linear,
// clamped), 8-bit colour with its mip chain (imagery, ground detail), and
// binding a texture to its unit of the one table (gl/texture_units.h).

#include "gl/gl_objects.h"
#include "gl/texture_units.h"

namespace ig::gl {

// The largest texture side the context allows.
int max_texture_size();
// width x height float heights, row-major.
Texture upload_height_texture(int width, int height, const float* heights);
// The central differences of those heights, (h[i+1] - h[i-1], h[j+1] - h[j-1])
// per sample (edges clamped), RG16F, linear, clamped. Differences commute
// with bilinear filtering, so one filtered read gives what four filtered
// height reads a sample apart give (shaders/height_differences_texture.frag).
Texture upload_height_differences_texture(int width, int height, const float* heights);
// 8-bit colour (rgba: 4 channels, else 3), tightly packed, mipmapped
// (trilinear); repeat: wraps (a tiling texture), else clamps to the edge.
Texture upload_colour_texture(int width, int height, const unsigned char* pixels, bool rgba, bool repeat);
void bind_texture(TextureUnit unit, const Texture& texture);
void bind_texture(TextureUnit unit, GLuint texture);

}  // namespace ig::gl
