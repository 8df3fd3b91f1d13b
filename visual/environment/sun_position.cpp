#include "environment/sun_position.h"

#include <erfa.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace ig::environment {
namespace {

constexpr double kDegToRad = 0.017453292519943295;
constexpr double kHorizonDeg = -0.8334;  // sun's centre when its upper limb touches the horizon
constexpr double kTaperEndDeg = -5.0;

std::string when(const options::UtcDateTime& t, double seconds_after) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%06.3fZ + %g s", t.year, t.month, t.day, t.hour, t.minute,
                t.second, seconds_after);
  return buf;
}

// Saemundsson (Meeus, Astronomical Algorithms, 16.4) in arcminutes, scaled
// to the air's pressure and temperature as the NREL SPA does.
double saemundsson_deg(double e_deg, const Atmosphere& air) {
  const double r_arcmin = 1.02 / std::tan(kDegToRad * (e_deg + 10.3 / (e_deg + 5.11)));
  return r_arcmin / 60.0 * (air.pressure_hpa / 1010.0) * (283.0 / (273.0 + air.temperature_c));
}

}  // namespace

Atmosphere standard_atmosphere(double height_m) {
  const double h = std::clamp(std::isfinite(height_m) ? height_m : 0.0, -1000.0, 20000.0);
  Atmosphere a;
  if (h <= 11000.0) {
    a.temperature_c = 15.0 - 0.0065 * h;
    a.pressure_hpa = 1013.25 * std::pow(1.0 - 2.25577e-5 * h, 5.25588);
  } else {  // the isothermal layer above the tropopause
    a.temperature_c = -56.5;
    a.pressure_hpa = 226.32 * std::exp(-(h - 11000.0) / 6341.62);
  }
  return a;
}

glm::dvec3 SunPosition::enu() const {
  const double e = elevation_deg * kDegToRad, a = azimuth_deg * kDegToRad;
  return {std::sin(a) * std::cos(e), std::cos(a) * std::cos(e), std::sin(e)};
}

double atmospheric_refraction_deg(double e_deg, const Atmosphere& air) {
  if (!std::isfinite(e_deg) || e_deg <= kTaperEndDeg) return 0.0;
  if (e_deg >= kHorizonDeg) return saemundsson_deg(e_deg, air);
  return saemundsson_deg(kHorizonDeg, air) * (e_deg - kTaperEndDeg) / (kHorizonDeg - kTaperEndDeg);
}

SunPosition sun_position(const options::UtcDateTime& t, double seconds_after, const Observer& o,
                         const Atmosphere& air) {
  if (!std::isfinite(seconds_after) || !std::isfinite(o.latitude_deg) || !std::isfinite(o.longitude_deg) ||
      !std::isfinite(o.height_m) || !std::isfinite(t.second))
    throw std::invalid_argument("sun position at " + when(t, seconds_after) + ": a non-finite time or place");
  double utc1 = 0.0, utc2 = 0.0;
  // Status > 0 is a warning only (a year beyond ERFA's leap-second table).
  if (eraDtf2d("UTC", t.year, t.month, t.day, t.hour, t.minute, t.second, &utc1, &utc2) < 0)
    throw std::invalid_argument("sun position at " + when(t, seconds_after) + ": not a valid UTC date and time");
  utc2 += seconds_after / 86400.0;

  // Astrometry parameters for this observer: its barycentric position and
  // velocity, the direction of the sun from it (topocentric), the
  // bias-precession-nutation matrix and the Earth's rotation. No refraction
  // (pressure 0) and no polar motion (below 0.5").
  eraASTROM astrom;
  double eo = 0.0;
  const double lat = std::clamp(o.latitude_deg, -90.0, 90.0) * kDegToRad;
  if (eraApco13(utc1, utc2, /*dut1=*/0.0, o.longitude_deg * kDegToRad, lat, o.height_m, 0.0, 0.0,
                /*phpa=*/0.0, 0.0, 0.0, 0.55, &astrom, &eo) < 0)
    throw std::invalid_argument("sun position at " + when(t, seconds_after) + ": date outside ERFA's range");
  // eh is the unit vector from the sun to the observer.
  double towards_sun[3] = {-astrom.eh[0], -astrom.eh[1], -astrom.eh[2]};
  double aberrated[3], cirs[3];
  eraAb(towards_sun, astrom.v, astrom.em, astrom.bm1, aberrated);
  eraRxp(astrom.bpn, aberrated, cirs);
  double ri = 0.0, di = 0.0;
  eraC2s(cirs, &ri, &di);
  double azimuth = 0.0, zenith = 0.0, hour_angle = 0.0, dec = 0.0, ra = 0.0;
  eraAtioq(eraAnp(ri), di, &astrom, &azimuth, &zenith, &hour_angle, &dec, &ra);

  SunPosition s;
  s.geometric_elevation_deg = 90.0 - zenith / kDegToRad;
  s.elevation_deg = s.geometric_elevation_deg + atmospheric_refraction_deg(s.geometric_elevation_deg, air);
  s.azimuth_deg = eraAnp(azimuth) / kDegToRad;
  return s;
}

SunPosition sun_position(const options::UtcDateTime& t, double seconds_after, const Observer& o) {
  return sun_position(t, seconds_after, o, standard_atmosphere(o.height_m));
}

}  // namespace ig::environment
