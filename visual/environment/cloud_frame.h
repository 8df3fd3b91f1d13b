#pragma once
// What the cloud pass needs of the layers for one view, worked out on the
// CPU in double precision: each layer's slab, extinction, the noise
// threshold its coverage gives, and where the eye is on the repeating noise
// field (wrapped there, so the shader's coordinates stay small however far
// the eye flies; the wind's drift is added here too). Layers with nothing to
// draw (coverage 0) are left out. No GL.

#include <array>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "environment/cloud_layers.h"
#include "environment/sky_light.h"

namespace ig::environment {

// Per layer, four vec4s (the shader's u_layer[4 * i + k]):
// [0] base, top, transition band (m above sea level), extinction (1/m);
// [1] noise threshold (1 - coverage; < 0 overcast), form (0 stratiform,
//     1 cumuliform, 2 cirriform), march steps a stretch, noise texel size (m);
// [2] the eye's noise coordinate (wrapped), 0, 0;
// [3] metres -> noise coordinates: the 2x2 matrix, column-major.
struct CloudFrame {
  int layers = 0;
  std::array<glm::vec4, 4 * kMaxCloudLayers> packed{};
  // The light the clouds get: the sun's direct light and direction, the sky's
  // light on a cloud top and base, and the share of light left on the
  // ground in a cloud's shadow (the sky's share of the ground's light).
  glm::vec3 sun_direction{0.0f, 0.0f, 1.0f};
  glm::vec3 sun_light{0.0f};
  glm::vec3 sky_light_top{0.0f}, sky_light_base{0.0f};
  float shadow_floor = 1.0f;
};

// eye: terrain-local metres (x east, y north, z height above sea level);
// time_s: the scene's clock, which the wind drifts the layers with.
CloudFrame cloud_frame(const options::CloudLayers& layers, const glm::dvec3& eye, double time_s, const SkyLight& sky);

}  // namespace ig::environment
