#pragma once
// How the terrain and the sky are shaded, one struct for every place that
// sets it: the scenario file (render.sun_direction, sky_zenith_rgb,
// sky_horizon_rgb, fog_visibility_m, environment.time_utc and
// environment.clouds;
// io/scenario.cpp), Modbus (the fog register) and the renderer
// (render::TerrainScene, the sky pass, the per-frame sun of
// session::ScenarioRunner).

#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "options/cloud_options.h"

namespace ig::options {

// A UTC calendar date and time of day (environment.time_utc, ISO 8601).
struct UtcDateTime {
  int year = 2000, month = 1, day = 1;
  int hour = 0, minute = 0;
  double second = 0.0;  // [0, 60)
  bool operator==(const UtcDateTime&) const = default;
};

struct ShadingOptions {
  // Used when neither sun_direction nor time_utc is given.
  static constexpr glm::vec3 kDefaultSunDirection{-0.4f, 0.5f, 0.75f};

  // Towards the sun in terrain-local axes (x east, y grid north, z up),
  // normalised. Set: used as is (it overrides time_utc).
  std::optional<glm::vec3> sun_direction;
  // The scene's UTC time at sim time 0; the sun then follows the clock and
  // the eye's latitude/longitude (environment/sun_position.h). Needs a
  // georeferenced terrain (or terrain.generator.origin).
  std::optional<UtcDateTime> time_utc;
  // The clear-day sky (sun 20 deg or more above the horizon); lower suns
  // blend towards the dusk and night colours of environment/sky_light.h.
  glm::vec3 sky_zenith{0.22f, 0.42f, 0.78f};    // RGB in [0, 1]
  glm::vec3 sky_horizon{0.70f, 0.80f, 0.92f};   // RGB in [0, 1], also the fog colour
  double fog_visibility_m = 60000.0;            // distance where fog reaches ~98 %; 0 = off
  static constexpr double kMaxFogVisibilityM = 1e9;  // fog_visibility_m in [0, kMaxFogVisibilityM]
  // Ground detail fixed to the terrain (render.ground_detail): materials and
  // grain that give a low-flying pilot cues of speed and height.
  bool ground_detail = true;
  // Deferred shading (render.deferred_shading): the terrain passes store each
  // pixel's surface coordinate, footprint and distance, and one full-screen
  // pass shades every covered pixel once (shaders/shade_deferred.frag). The
  // picture is the same; only single-sampled frames (fxaa, off) can.
  bool deferred_shading = true;
  // Cloud layers (environment.clouds; a CIGI host's Weather Control
  // replaces them): none by default, and then nothing of the clouds is made.
  CloudLayers clouds;
};

}  // namespace ig::options
