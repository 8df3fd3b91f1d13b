#include "environment/sky_light.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace ig::environment {
namespace {

constexpr double kDegToRad = 0.017453292519943295;

// The sky and the light from it at one sun elevation; between two keys the
// values are blended linearly. Display values (the frame is not
// tone-mapped), chosen by eye on rendered dusk and night frames: the sky
// darkens as the sun sinks; the ambient (sky) light grows while the direct
// sun fades, as the light at dusk is all diffuse, so that what lights level
// ground (SkyLight::ground_light) still falls monotonically (the unit test
// checks both); the glow peaks around sunset. The day key
// (kDayElevationDeg) takes the configured sky colours.
struct Key {
  double elevation_deg;
  glm::vec3 zenith, horizon, ambient, glow, twilight_light;
};

// clang-format off
constexpr std::array<Key, 8> kKeys = {{
    // elevation  zenith                   horizon                  ambient                  glow                     twilight light
    {-18.0, {0.020f, 0.030f, 0.060f}, {0.050f, 0.060f, 0.090f}, {0.060f, 0.070f, 0.100f}, {0.00f, 0.00f, 0.00f}, {0.00f, 0.00f, 0.00f}},
    {-12.0, {0.030f, 0.045f, 0.095f}, {0.080f, 0.085f, 0.120f}, {0.100f, 0.115f, 0.160f}, {0.03f, 0.01f, 0.00f}, {0.02f, 0.02f, 0.03f}},
    {-6.0, {0.070f, 0.110f, 0.220f}, {0.220f, 0.200f, 0.260f}, {0.200f, 0.215f, 0.280f}, {0.18f, 0.07f, 0.02f}, {0.20f, 0.15f, 0.17f}},
    {-3.0, {0.110f, 0.190f, 0.380f}, {0.450f, 0.370f, 0.390f}, {0.280f, 0.280f, 0.340f}, {0.32f, 0.13f, 0.03f}, {0.36f, 0.26f, 0.25f}},
    {0.0, {0.160f, 0.280f, 0.540f}, {0.640f, 0.540f, 0.510f}, {0.330f, 0.320f, 0.340f}, {0.35f, 0.16f, 0.04f}, {0.40f, 0.27f, 0.22f}},
    {3.0, {0.185f, 0.340f, 0.640f}, {0.700f, 0.660f, 0.640f}, {0.370f, 0.365f, 0.370f}, {0.25f, 0.13f, 0.04f}, {0.20f, 0.13f, 0.10f}},
    {8.0, {0.200f, 0.380f, 0.720f}, {0.720f, 0.740f, 0.760f}, {0.390f, 0.390f, 0.390f}, {0.10f, 0.06f, 0.02f}, {0.00f, 0.00f, 0.00f}},
    {kDayElevationDeg, {}, {}, {0.250f, 0.250f, 0.250f}, {0.00f, 0.00f, 0.00f}, {0.00f, 0.00f, 0.00f}},
}};
// clang-format on

// Relative air mass along the line of sight to the sun (Kasten and Young
// 1989), 1 at the zenith, about 38 at the horizon.
double air_mass(double elevation_deg) {
  const double e = std::max(elevation_deg, -0.5);
  return 1.0 / (std::sin(e * kDegToRad) + 0.50572 * std::pow(e + 6.07995, -1.6364));
}

// Sunlight's transmission per channel relative to a sun at kDayElevationDeg
// (so day light stays white): blue scatters out of the beam first, then
// green, so a low sun is orange and a setting one red. The extinction
// coefficients are per unit air mass, chosen by eye.
glm::vec3 sun_transmission(double elevation_deg) {
  const glm::dvec3 k(0.03, 0.07, 0.15);
  const double extra = std::max(air_mass(elevation_deg) - air_mass(kDayElevationDeg), 0.0);
  return glm::vec3(glm::exp(-k * extra));
}

}  // namespace

SkyLight sky_light_for(const glm::vec3& sun_direction, const options::ShadingOptions& day) {
  SkyLight s;
  const float length = glm::length(sun_direction);
  const bool usable = std::isfinite(length) && length > 0.0f;
  s.sun_direction = usable ? sun_direction / length : glm::normalize(options::ShadingOptions::kDefaultSunDirection);
  const double e = std::asin(std::clamp(double(s.sun_direction.z), -1.0, 1.0)) / kDegToRad;
  s.sun_elevation_deg = e;

  // Sky, ambient, glow and twilight light from the keys.
  auto key = [&](std::size_t k) {
    Key out = kKeys[k];
    if (out.elevation_deg == kDayElevationDeg) {
      out.zenith = day.sky_zenith;
      out.horizon = day.sky_horizon;
    }
    return out;
  };
  Key a = key(0), b = key(0);
  float w = 0.0f;
  if (e >= kKeys.back().elevation_deg) {
    a = b = key(kKeys.size() - 1);
  } else if (e > kKeys.front().elevation_deg) {
    std::size_t k = 1;
    while (kKeys[k].elevation_deg < e) ++k;
    a = key(k - 1);
    b = key(k);
    w = float((e - a.elevation_deg) / (b.elevation_deg - a.elevation_deg));
  }
  s.sky_zenith = glm::mix(a.zenith, b.zenith, w);
  s.sky_horizon = glm::mix(a.horizon, b.horizon, w);
  s.ambient = glm::mix(a.ambient, b.ambient, w);
  s.horizon_glow = glm::mix(a.glow, b.glow, w);
  const glm::vec3 twilight = glm::mix(a.twilight_light, b.twilight_light, w);

  // Direct sunlight: reddened by the air mass, gone once the disc has set
  // (its centre 0.3 deg below the apparent horizon).
  const glm::vec3 transmission = sun_transmission(e);
  const float disc_visible = float(glm::smoothstep(-0.3, 0.3, e));
  s.sun_light = 0.85f * transmission * disc_visible;
  s.light_colour = glm::clamp(s.sun_light + twilight, 0.0f, 1.0f);
  const glm::vec3 white_disc(1.0f, 0.97f, 0.9f);
  s.sun_disc = white_disc * transmission / std::max({transmission.r, transmission.g, transmission.b});

  // The light comes from the sun's azimuth, at least kMinLightElevationDeg up.
  s.light_direction = s.sun_direction;
  if (e < kMinLightElevationDeg) {
    const glm::vec2 horizontal(s.sun_direction.x, s.sun_direction.y);
    const float len = glm::length(horizontal);
    const glm::vec2 h = len > 1e-6f ? horizontal / len : glm::vec2(0.0f, 1.0f);
    const double m = kMinLightElevationDeg * kDegToRad;
    s.light_direction = glm::vec3(h * float(std::cos(m)), float(std::sin(m)));
  }
  return s;
}

}  // namespace ig::environment
