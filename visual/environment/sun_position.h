#pragma once
// Where the sun stands for an observer on the Earth at a UTC time: elevation
// and azimuth, from the IAU SOFA routines (ERFA, Debian's liberfa). No GL.
//
// The chain: ERFA's eraApco13 (Earth ephemeris, precession-nutation, Earth
// rotation with UT1 = UTC, i.e. within 0.9 s) gives the observer's
// heliocentric direction, so parallax is included; annual aberration
// (eraAb), CIRS -> observed (eraAtioq) without ERFA's refraction, whose
// model fails near the horizon. Refraction is added separately
// (atmospheric_refraction_deg), as the NREL SPA does. Error against the
// NREL SPA worked example: under 0.001 deg (environment/test).

#include <glm/vec3.hpp>

#include "options/shading_options.h"

namespace ig::environment {

struct Observer {
  double latitude_deg = 0.0;   // geodetic, WGS84
  double longitude_deg = 0.0;  // east positive
  double height_m = 0.0;       // above the ellipsoid (the geoid's 100 m make no visible difference)
};

// Air at the observer, for refraction.
struct Atmosphere {
  double pressure_hpa = 1010.0;
  double temperature_c = 10.0;
};

// The ICAO standard atmosphere at a height (pressure and temperature).
Atmosphere standard_atmosphere(double height_m);

struct SunPosition {
  double geometric_elevation_deg = 0.0;  // without refraction
  double elevation_deg = 0.0;            // apparent: with refraction (what the eye sees)
  double azimuth_deg = 0.0;              // clockwise from true north, [0, 360)
  // Unit vector towards the apparent sun in the observer's east-north-up frame.
  glm::dvec3 enu() const;
};

// Refraction (deg) to add to a geometric elevation: Saemundsson's formula
// scaled by pressure and temperature (the NREL SPA's), for the sun's centre
// down to -0.83 deg (its upper limb on the horizon); below that, where it
// has no observable meaning, it tapers to 0 at -5 deg so the apparent
// elevation stays continuous and increasing.
double atmospheric_refraction_deg(double geometric_elevation_deg, const Atmosphere& air);

// The sun at `utc` plus `seconds_after` (may be negative), seen from
// `observer` through `air`. Throws std::invalid_argument for a date ERFA
// refuses (a calendar field out of range, a year before -4799) or a
// non-finite input.
SunPosition sun_position(const options::UtcDateTime& utc, double seconds_after, const Observer& observer,
                         const Atmosphere& air);
// With the standard atmosphere at the observer's height.
SunPosition sun_position(const options::UtcDateTime& utc, double seconds_after, const Observer& observer);

}  // namespace ig::environment
