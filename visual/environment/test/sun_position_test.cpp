// The sun's position (ERFA) against two independent sources:
// - NOAA's "General Solar Position Calculations" (the fractional-year series
//   for the declination and the equation of time), implemented here from
//   their published formulas; their own accuracy is a few tenths of a degree,
//   so agreement within 0.6 deg is asked;
// - the worked example of the NREL Solar Position Algorithm (Reda and
//   Andreas, NREL/TP-560-34302: Golden, Colorado, 17 October 2003), whose
//   published figures carry 1e-6 deg and claim 0.0003 deg.
#include "environment/sun_position.h"

#include <chrono>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace {

using ig::environment::Atmosphere;
using ig::environment::Observer;
using ig::environment::sun_position;
using ig::options::UtcDateTime;

constexpr double kPi = 3.14159265358979323846;
constexpr double kRad = kPi / 180.0;

struct Angles {
  double elevation_deg, azimuth_deg;
};

// NOAA Global Monitoring Laboratory, "General Solar Position Calculations":
// fractional year gamma, then the declination and equation of time series,
// true solar time, hour angle and zenith. The page's azimuth formula is an
// arccos whose quadrant it leaves open; the azimuth here comes from the same
// hour angle and declination by the usual spherical triangle instead.
Angles noaa_general(const UtcDateTime& t, double lat_deg, double lon_deg) {
  using namespace std::chrono;
  const year_month_day ymd{year(t.year), month(unsigned(t.month)), day(unsigned(t.day))};
  const int day_of_year = int((sys_days(ymd) - sys_days(year(t.year) / January / 1)).count()) + 1;
  const double days_in_year = year(t.year).is_leap() ? 366.0 : 365.0;
  const double hour = t.hour + t.minute / 60.0 + t.second / 3600.0;
  const double g = 2.0 * kPi / days_in_year * (day_of_year - 1 + (hour - 12.0) / 24.0);
  const double eqtime = 229.18 * (0.000075 + 0.001868 * std::cos(g) - 0.032077 * std::sin(g) -
                                  0.014615 * std::cos(2 * g) - 0.040849 * std::sin(2 * g));
  const double decl = 0.006918 - 0.399912 * std::cos(g) + 0.070257 * std::sin(g) - 0.006758 * std::cos(2 * g) +
                      0.000907 * std::sin(2 * g) - 0.002697 * std::cos(3 * g) + 0.00148 * std::sin(3 * g);
  const double time_offset = eqtime + 4.0 * lon_deg;  // minutes; the time is UTC (zone 0)
  const double true_solar_min = t.hour * 60.0 + t.minute + t.second / 60.0 + time_offset;
  const double ha = (true_solar_min / 4.0 - 180.0) * kRad;
  const double lat = lat_deg * kRad;
  const double cos_zenith = std::sin(lat) * std::sin(decl) + std::cos(lat) * std::cos(decl) * std::cos(ha);
  Angles a;
  a.elevation_deg = 90.0 - std::acos(std::clamp(cos_zenith, -1.0, 1.0)) / kRad;
  // Azimuth from the south, westward, then turned to clockwise from north.
  const double from_south = std::atan2(std::sin(ha), std::cos(ha) * std::sin(lat) - std::tan(decl) * std::cos(lat));
  a.azimuth_deg = std::fmod(from_south / kRad + 180.0 + 360.0, 360.0);
  return a;
}

double azimuth_difference(double a, double b) { return std::fabs(std::remainder(a - b, 360.0)); }

UtcDateTime utc(int y, int mo, int d, int h, int mi, double s = 0.0) { return UtcDateTime{y, mo, d, h, mi, s}; }

struct Case {
  const char* label;
  UtcDateTime time;
  double lat, lon;
};

TEST(SunPosition, MatchesNoaaGeneralSolarPosition) {
  const Case cases[] = {
      {"Sierra Nevada, summer morning", utc(2026, 6, 21, 15, 0), 37.3, -118.6},
      {"Sierra Nevada, summer afternoon", utc(2026, 6, 21, 23, 30), 37.3, -118.6},
      {"Sierra Nevada, winter noon", utc(2026, 12, 21, 20, 0), 37.3, -118.6},
      {"Sierra Nevada, night", utc(2026, 6, 21, 8, 0), 37.3, -118.6},
      {"Alps, equinox evening", utc(2026, 3, 20, 16, 45), 46.5, 7.9},
      {"Cape Town, autumn morning", utc(2026, 3, 15, 7, 30), -33.92, 18.42},
      {"Sydney, midwinter afternoon", utc(2026, 6, 21, 4, 0), -33.87, 151.21},
      {"Quito, near the equator", utc(2026, 9, 1, 14, 0), -0.18, -78.47},
      {"Svalbard, midnight sun", utc(2026, 6, 21, 22, 0), 78.22, 15.65},
      {"Svalbard, polar night", utc(2026, 12, 21, 11, 0), 78.22, 15.65},
      {"McMurdo, midnight sun", utc(2026, 12, 21, 12, 0), -77.85, 166.67},
      {"Alert, spring", utc(2025, 4, 10, 18, 0), 82.5, -62.3},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.label);
    const auto s = sun_position(c.time, 0.0, Observer{c.lat, c.lon, 0.0});
    const Angles n = noaa_general(c.time, c.lat, c.lon);
    EXPECT_NEAR(s.geometric_elevation_deg, n.elevation_deg, 0.6);
    EXPECT_LT(azimuth_difference(s.azimuth_deg, n.azimuth_deg), 0.6) << s.azimuth_deg << " vs " << n.azimuth_deg;
  }
}

TEST(SunPosition, MatchesNoaaThroughTheYearAndDay) {
  // Every month, every three hours, at three latitudes. The angle between the
  // two directions is what the eye sees; the azimuth alone is compared only
  // within 60 deg of the horizon, as near the zenith or nadir a small
  // angle is a large turn in azimuth.
  const double places[][2] = {{37.3, -118.6}, {-45.0, 170.0}, {64.1, -21.9}};
  double worst_el = 0.0, worst_az = 0.0, worst_angle = 0.0;
  for (const auto& p : places)
    for (int month = 1; month <= 12; ++month)
      for (int hour = 0; hour < 24; hour += 3) {
        const UtcDateTime t = utc(2026, month, 11, hour, 20);
        const auto s = sun_position(t, 0.0, Observer{p[0], p[1], 0.0});
        const Angles n = noaa_general(t, p[0], p[1]);
        worst_el = std::max(worst_el, std::fabs(s.geometric_elevation_deg - n.elevation_deg));
        if (std::fabs(n.elevation_deg) < 60.0)
          worst_az = std::max(worst_az, azimuth_difference(s.azimuth_deg, n.azimuth_deg));
        const double e1 = s.geometric_elevation_deg * kRad, e2 = n.elevation_deg * kRad;
        const double da = (s.azimuth_deg - n.azimuth_deg) * kRad;
        const double cos_angle = std::sin(e1) * std::sin(e2) + std::cos(e1) * std::cos(e2) * std::cos(da);
        worst_angle = std::max(worst_angle, std::acos(std::clamp(cos_angle, -1.0, 1.0)) / kRad);
      }
  EXPECT_LT(worst_el, 0.6);
  EXPECT_LT(worst_az, 0.6);
  EXPECT_LT(worst_angle, 0.6);
  std::printf("worst against NOAA: elevation %.3f deg, azimuth %.3f deg, angle %.3f deg\n", worst_el, worst_az,
              worst_angle);
}

TEST(SunPosition, MatchesTheNrelSpaWorkedExample) {
  // 2003-10-17 12:30:30 local (UTC-7), 39.742476 N, 105.1786 W, 1830.14 m,
  // 820 hPa, 11 C. Published: topocentric elevation 39.872046 deg without
  // refraction, 39.888378 with, azimuth 194.340241 deg. The SPA takes
  // TT - UT = 67 s where ERFA's leap seconds give 64.184 s: the sun moves
  // 0.00003 deg in the difference.
  const Observer golden{39.742476, -105.1786, 1830.14};
  const Atmosphere air{820.0, 11.0};
  const auto s = sun_position(utc(2003, 10, 17, 19, 30, 30.0), 0.0, golden, air);
  EXPECT_NEAR(s.geometric_elevation_deg, 39.872046, 0.001);
  EXPECT_NEAR(s.elevation_deg, 39.888378, 0.001);
  EXPECT_NEAR(s.azimuth_deg, 194.340241, 0.001);
}

TEST(SunPosition, TheClockAdvancesTheSun) {
  // seconds_after moves the same instant as the calendar does, across midnight too.
  const Observer o{37.3, -118.6, 2000.0};
  const auto direct = sun_position(utc(2026, 6, 22, 0, 15), 0.0, o);
  const auto advanced = sun_position(utc(2026, 6, 21, 23, 45), 1800.0, o);
  EXPECT_NEAR(direct.elevation_deg, advanced.elevation_deg, 1e-6);
  EXPECT_NEAR(direct.azimuth_deg, advanced.azimuth_deg, 1e-6);
  // Late afternoon in California: the sun sinks in the west.
  const auto later = sun_position(utc(2026, 6, 21, 23, 45), 3600.0, o);
  EXPECT_LT(later.elevation_deg, advanced.elevation_deg - 5.0);
  EXPECT_GT(advanced.azimuth_deg, 250.0);
  EXPECT_LT(advanced.azimuth_deg, 310.0);
}

TEST(SunPosition, EnuVectorPointsAtTheSun) {
  const auto s = sun_position(utc(2026, 6, 21, 15, 0), 0.0, Observer{37.3, -118.6, 0.0});
  const glm::dvec3 v = s.enu();
  EXPECT_NEAR(glm::length(v), 1.0, 1e-12);
  EXPECT_NEAR(std::asin(v.z) / kRad, s.elevation_deg, 1e-9);
  EXPECT_NEAR(std::fmod(std::atan2(v.x, v.y) / kRad + 360.0, 360.0), s.azimuth_deg, 1e-9);
  // A summer morning: the sun is in the east (x > 0), north of east (y > 0).
  EXPECT_GT(v.x, 0.5);
  EXPECT_GT(v.y, 0.0);
}

TEST(SunPosition, RefractionLiftsTheSunMostAtTheHorizon) {
  const Atmosphere standard{1010.0, 10.0};
  // Saemundsson: 29 arcmin for a geometric elevation of 0, 1 arcmin at 45 deg.
  EXPECT_NEAR(ig::environment::atmospheric_refraction_deg(0.0, standard) * 60.0, 29.0, 0.5);
  EXPECT_NEAR(ig::environment::atmospheric_refraction_deg(45.0, standard) * 60.0, 1.0, 0.05);
  EXPECT_NEAR(ig::environment::atmospheric_refraction_deg(90.0, standard), 0.0, 1e-4);
  EXPECT_EQ(ig::environment::atmospheric_refraction_deg(-5.0, standard), 0.0);
  EXPECT_EQ(ig::environment::atmospheric_refraction_deg(-30.0, standard), 0.0);
  // Thinner air refracts less.
  EXPECT_LT(ig::environment::atmospheric_refraction_deg(1.0, ig::environment::standard_atmosphere(4000.0)),
            ig::environment::atmospheric_refraction_deg(1.0, standard));
  // The apparent elevation rises with the geometric one, without jumps.
  double previous = -1e9;
  for (double e = -10.0; e <= 10.0; e += 0.01) {
    const double apparent = e + ig::environment::atmospheric_refraction_deg(e, standard);
    EXPECT_GT(apparent, previous) << e;
    if (previous > -1e9) {
      EXPECT_LT(apparent - previous, 0.02) << e;
    }
    previous = apparent;
  }
}

TEST(SunPosition, StandardAtmosphere) {
  EXPECT_NEAR(ig::environment::standard_atmosphere(0.0).pressure_hpa, 1013.25, 1e-9);
  EXPECT_NEAR(ig::environment::standard_atmosphere(0.0).temperature_c, 15.0, 1e-9);
  EXPECT_NEAR(ig::environment::standard_atmosphere(5000.0).pressure_hpa, 540.2, 0.5);  // ICAO table
  EXPECT_NEAR(ig::environment::standard_atmosphere(11000.0).temperature_c, -56.5, 1e-9);
}

TEST(SunPosition, BadInputIsRefusedWithAReason) {
  const Observer o{37.3, -118.6, 0.0};
  EXPECT_THROW(sun_position(utc(2026, 13, 1, 0, 0), 0.0, o), std::invalid_argument);
  EXPECT_THROW(sun_position(utc(2026, 2, 30, 0, 0), 0.0, o), std::invalid_argument);
  EXPECT_THROW(sun_position(utc(2026, 6, 21, 12, 0), std::nan(""), o), std::invalid_argument);
  EXPECT_THROW(sun_position(utc(2026, 6, 21, 12, 0), 0.0, Observer{std::nan(""), 0.0, 0.0}), std::invalid_argument);
  try {
    sun_position(utc(2026, 13, 1, 0, 0), 0.0, o);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("2026-13-01"), std::string::npos) << e.what();
  }
}

}  // namespace
