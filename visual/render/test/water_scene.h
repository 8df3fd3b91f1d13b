#pragma once
// A coast for the GL water tests, needing no real DEM: a 401 x 401 GeoTIFF
// (EPSG:4326, 1/1200 degree from 119 W, 37.5 N as test_geotiff.h writes
// it: about 92 x 74 m) whose south is sea at exactly 0 m, found by
// terrain.water "auto", behind a winding coast of every angle, the land
// rising north from it. And a scenario over it with a fixed sun.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "io/scenario.h"
#include "terrain/test/test_geotiff.h"

namespace water_scene {

inline constexpr int kSide = 401;

// The coast's row at column i (the sea is below it).
inline double coast_row(double i) { return 150.0 + 40.0 * std::sin(i / 60.0) + 0.3 * (i - 200.0); }

// Writes the DEM (rows south first) and returns its path.
inline std::string write_coast_dem(const std::filesystem::path& dir) {
  std::vector<float> h(std::size_t(kSide) * kSide);
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i) {
      const double above = j - coast_row(i);
      const double bumps = 6.0 * std::sin(i * 0.37) * std::sin(j * 0.29) + 3.0 * std::sin(i * 1.3 + j * 0.7);
      h[std::size_t(j) * kSide + i] = above < 0.0 ? 0.0f : float(2.0 + 3.0 * above + std::max(0.0, above) * 0.05 * bumps);
    }
  const std::string path = (dir / "coast.tif").string();
  ig::terrain::test::write_south_first_geotiff(path, kSide, kSide, h, -32768.0);
  return path;
}

// Latitude and longitude of sample (i, j) (south-up) of that DEM.
inline double lat_of(double j) { return 37.5 - (kSide - 0.5 - j) / 1200.0; }
inline double lon_of(double i) { return -119.0 + (i + 0.5) / 1200.0; }

// The eye over sample (i, j) at z m above sea level, looking along
// heading / pitch, the sun fixed towards `sun` ("[x, y, z]", terrain axes),
// a w x h frame; frames at sim time 0 and 1 s.
inline ig::io::Scenario coast_scenario(const std::string& dem, double i, double j, double z, double heading,
                                       double pitch, const std::string& sun, int w = 320, int h = 240) {
  char key[256];
  std::snprintf(key, sizeof key, R"({ "t": 0, "position": [%.9f, %.9f, %.3f], "hpr": [%.6f, %.6f, 0] })",
                lat_of(j), lon_of(i), z, heading, pitch);
  const std::string text = std::string(R"({
    "name": "coast",
    "terrain": { "file": ")") + dem + R"(" },
    "render": { "width": )" + std::to_string(w) + R"(, "height": )" + std::to_string(h) +
                           R"(, "fov_y_deg": 45, "sun_direction": )" + sun + R"(, "fog_visibility_m": 60000 },
    "path": { "frame": "geodetic", "altitude": "msl", "keys": [ )" + key + R"( ] },
    "time": { "step_s": 1, "duration_s": 1 }
  })";
  return ig::io::parse_scenario(text);
}

}  // namespace water_scene
