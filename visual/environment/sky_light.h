#pragma once
// The light and the sky for a sun direction, computed once a frame on the
// CPU and handed to the shaders as uniforms: day, dusk and night from the
// sun's elevation alone. No GL.
//
// Day (sun >= 20 deg): the configured sky colours, ambient 0.25 and a white
// sun of 0.85 (the shading the IG always had). Lower, the sunlight reddens
// with the air mass it crosses and fades out just below the horizon while
// the diffuse sky light takes over; the sky darkens through civil (0 to
// -6 deg) and nautical (-6 to -12 deg) twilight to a night sky at -18 deg,
// with an orange glow on the horizon towards the sun at dusk. So the terrain
// stays readable at dusk, the directional light never drops below
// kMinLightElevationDeg: after sunset it is the twilight sky's light from
// the sunward horizon, which still models the relief.

#include <algorithm>

#include <glm/vec3.hpp>

#include "options/shading_options.h"

namespace ig::environment {

constexpr double kDayElevationDeg = 20.0;      // at and above: the configured day sky
constexpr double kNightElevationDeg = -18.0;   // at and below: night (astronomical twilight over)
constexpr double kMinLightElevationDeg = 4.0;  // the directional light's lowest elevation

struct SkyLight {
  double sun_elevation_deg = 0.0;
  glm::vec3 sun_direction{0.0f, 0.0f, 1.0f};    // towards the sun (terrain-local, unit): the sky's sun disc
  glm::vec3 light_direction{0.0f, 0.0f, 1.0f};  // the directional light (terrain-local, unit)
  glm::vec3 light_colour{0.85f};                // the directional light's RGB (multiplies n.l)
  glm::vec3 ambient{0.25f};                     // light from the whole sky, RGB
  glm::vec3 sky_zenith{0.0f};                   // sky overhead
  glm::vec3 sky_horizon{0.0f};                  // sky at the horizon; also the fog colour
  glm::vec3 horizon_glow{0.0f};                 // added to the sky towards the sun, low on the horizon
  glm::vec3 sun_disc{0.0f};                     // colour of the sun's disc
  glm::vec3 sun_light{0.0f};                    // the sun's own light (no twilight): 0 once the disc has set;
                                                // what a water surface mirrors in its glint

  // Luma of the light on level ground (normal straight up): ambient plus
  // the directional light at its elevation.
  float ground_light() const;
};

// The light and sky for a (non-zero) direction towards the sun in
// terrain-local axes; `day` gives the day sky colours. Every RGB is in
// [0, 1]. Brightness falls monotonically with the sun's elevation.
SkyLight sky_light_for(const glm::vec3& sun_direction, const options::ShadingOptions& day);

// Rec. 709 luma weights of an RGB.
inline float luma(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

inline float SkyLight::ground_light() const {
  return luma(ambient + light_colour * std::max(light_direction.z, 0.0f));
}

}  // namespace ig::environment
