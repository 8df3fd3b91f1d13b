// Light and sky from the sun's elevation (environment/sky_light.h): day as
// the IG always shaded it, night darker than dusk darker than day, and the
// sky, the direct light and the light on level ground monotone in the
// elevation.
#include "environment/sky_light.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace {

using ig::environment::luma;
using ig::environment::SkyLight;
using ig::environment::sky_light_for;
using ig::options::ShadingOptions;

constexpr double kRad = 0.017453292519943295;

// A sun at `elevation_deg`, azimuth 250 deg (west-south-west).
glm::vec3 sun_at(double elevation_deg, double azimuth_deg = 250.0) {
  const double e = elevation_deg * kRad, a = azimuth_deg * kRad;
  return glm::vec3(std::sin(a) * std::cos(e), std::cos(a) * std::cos(e), std::sin(e));
}

bool in_unit_cube(const glm::vec3& c) {
  return c.r >= 0.0f && c.g >= 0.0f && c.b >= 0.0f && c.r <= 1.0f && c.g <= 1.0f && c.b <= 1.0f;
}

TEST(SkyLight, DayIsTheConfiguredSkyAndTheClassicLight) {
  ShadingOptions day;
  day.sky_zenith = {0.1f, 0.3f, 0.9f};
  day.sky_horizon = {0.6f, 0.7f, 0.8f};
  for (const double e : {20.0, 35.0, 90.0}) {
    SCOPED_TRACE(e);
    const SkyLight s = sky_light_for(sun_at(e) * 5.0f, day);  // any length
    EXPECT_NEAR(s.sun_elevation_deg, e, 1e-4);
    EXPECT_EQ(s.sky_zenith, day.sky_zenith);
    EXPECT_EQ(s.sky_horizon, day.sky_horizon);
    EXPECT_EQ(s.ambient, glm::vec3(0.25f));
    EXPECT_EQ(s.light_colour, glm::vec3(0.85f));
    EXPECT_EQ(s.horizon_glow, glm::vec3(0.0f));
    EXPECT_NEAR(glm::length(s.light_direction - glm::normalize(sun_at(e))), 0.0f, 1e-6f);
  }
}

TEST(SkyLight, NightIsDarkerThanDuskIsDarkerThanDay) {
  const ShadingOptions opts;
  const SkyLight day = sky_light_for(sun_at(45.0), opts);
  const SkyLight dusk = sky_light_for(sun_at(-3.0), opts);  // civil twilight
  const SkyLight night = sky_light_for(sun_at(-25.0), opts);
  for (auto part : {&SkyLight::sky_zenith, &SkyLight::sky_horizon, &SkyLight::light_colour}) {
    EXPECT_LT(luma(night.*part), luma(dusk.*part));
    EXPECT_LT(luma(dusk.*part), luma(day.*part));
  }
  EXPECT_LT(night.ground_light(), dusk.ground_light());
  EXPECT_LT(dusk.ground_light(), day.ground_light());
  // At dusk the light is mostly the sky's: more ambient than by day.
  EXPECT_GT(luma(dusk.ambient), luma(night.ambient));
  EXPECT_GT(luma(dusk.ambient), luma(dusk.light_colour));
  // Night: a dark sky (under 10 % even at the horizon) and a dim ambient.
  EXPECT_LT(luma(night.sky_zenith), 0.04f);
  EXPECT_LT(luma(night.sky_horizon), 0.1f);
  EXPECT_LT(luma(night.ambient), 0.1f);
  EXPECT_EQ(night.light_colour, glm::vec3(0.0f));
  // Dusk: the glow towards the sun is there, and warm.
  EXPECT_GT(luma(dusk.horizon_glow), luma(day.horizon_glow) + 0.05f);
  EXPECT_GT(luma(dusk.horizon_glow), luma(night.horizon_glow) + 0.05f);
  EXPECT_GT(dusk.horizon_glow.r, 2.0f * dusk.horizon_glow.b);
}

TEST(SkyLight, BrightnessFallsMonotonicallyAsTheSunSinks) {
  const ShadingOptions opts;
  SkyLight above = sky_light_for(sun_at(90.0), opts);
  for (double e = 89.75; e >= -40.0; e -= 0.25) {
    SCOPED_TRACE(e);
    const SkyLight s = sky_light_for(sun_at(e), opts);
    for (auto part : {&SkyLight::sky_zenith, &SkyLight::sky_horizon, &SkyLight::ambient, &SkyLight::light_colour,
                      &SkyLight::horizon_glow, &SkyLight::sun_disc}) {
      EXPECT_TRUE(in_unit_cube(s.*part));
    }
    EXPECT_LE(luma(s.sky_zenith), luma(above.sky_zenith));
    EXPECT_LE(luma(s.sky_horizon), luma(above.sky_horizon));
    EXPECT_LE(s.ground_light(), above.ground_light());
    EXPECT_LE(luma(s.light_colour), luma(above.light_colour));
    above = s;
  }
}

TEST(SkyLight, LowSunIsWarmAndItsLightStaysAboveTheHorizon) {
  const ShadingOptions opts;
  const SkyLight high = sky_light_for(sun_at(40.0), opts);
  const SkyLight low = sky_light_for(sun_at(3.0), opts);
  const SkyLight set = sky_light_for(sun_at(-4.0), opts);
  // Redder as the sun sinks (blue scatters out first).
  EXPECT_GT(low.light_colour.r / low.light_colour.b, 1.5f * high.light_colour.r / high.light_colour.b);
  EXPECT_GT(low.sun_disc.r / low.sun_disc.b, high.sun_disc.r / high.sun_disc.b);
  // After sunset the light still comes from the sun's azimuth, from 4 deg up.
  for (const SkyLight* s : {&low, &set}) {
    EXPECT_NEAR(std::asin(s->light_direction.z) / kRad, ig::environment::kMinLightElevationDeg, 1e-4);
    EXPECT_NEAR(std::atan2(s->light_direction.x, s->light_direction.y) / kRad, 250.0 - 360.0, 1e-3);
  }
  EXPECT_GT(luma(set.light_colour), 0.02f);  // the twilight sky still models the relief
}

TEST(SkyLight, AZeroDirectionFallsBackToTheDefaultSun) {
  const SkyLight s = sky_light_for(glm::vec3(0.0f), ShadingOptions{});
  EXPECT_NEAR(glm::length(s.sun_direction), 1.0f, 1e-6f);
  EXPECT_GT(s.sun_elevation_deg, 20.0);
}

}  // namespace
