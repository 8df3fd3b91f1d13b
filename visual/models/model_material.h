#pragma once
// What a model's surface looks like, reduced to what the IG draws: glTF's
// base colour (factor and texture), its alpha mode and culling. The
// metallic-roughness, normal, occlusion and emissive inputs are not kept:
// the out-the-window entities are lit like the terrain, with one colour.

#include <cstdint>
#include <string>

#include <glm/vec4.hpp>

namespace ig::models {

// glTF's alphaMode: Opaque ignores alpha, Mask discards fragments whose
// alpha is below alpha_cutoff, Blend draws them translucent (after the
// opaque ones, back to front).
enum class AlphaMode : std::uint8_t { Opaque, Mask, Blend };
const char* alpha_mode_name(AlphaMode mode);

// A sampler's wrap mode along one texture axis (glTF's wrapS / wrapT).
enum class TextureWrap : std::uint8_t { Repeat, ClampToEdge, MirroredRepeat };

struct Material {
  std::string name;  // may be empty
  // Linear RGBA, each in [0, 1]; multiplies the texture's colour.
  glm::vec4 base_color{1.0f, 1.0f, 1.0f, 1.0f};
  int base_color_image = -1;  // index into Model::images; -1: no texture
  TextureWrap wrap_s = TextureWrap::Repeat;
  TextureWrap wrap_t = TextureWrap::Repeat;
  AlphaMode alpha_mode = AlphaMode::Opaque;
  float alpha_cutoff = 0.5f;  // used by AlphaMode::Mask only
  bool double_sided = false;  // false: back faces are culled
  bool unlit = false;         // KHR_materials_unlit: the base colour as is, no lighting
};

}  // namespace ig::models
