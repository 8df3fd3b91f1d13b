#pragma once
// How the terrain and the sky are shaded, one struct for every place that
// sets it: the scenario file (render.sun_direction, sky_zenith_rgb,
// sky_horizon_rgb, fog_visibility_m; io/scenario.cpp), Modbus (the fog
// register) and the renderer (render::TerrainScene, the sky pass).

#include <glm/vec3.hpp>

namespace ig::options {

struct ShadingOptions {
  glm::vec3 sun_direction{-0.4f, 0.5f, 0.75f};  // towards the sun, local ENU
  glm::vec3 sky_zenith{0.22f, 0.42f, 0.78f};    // RGB in [0, 1]
  glm::vec3 sky_horizon{0.70f, 0.80f, 0.92f};   // RGB in [0, 1], also the fog colour
  double fog_visibility_m = 60000.0;            // distance where fog reaches ~98 %; 0 = off
  // Ground detail fixed to the terrain (render.ground_detail): materials and
  // grain that give a low-flying pilot cues of speed and height.
  bool ground_detail = true;
};

}  // namespace ig::options
