#pragma once
// Where a terrain-local point lies on the Earth, for the sun: its WGS84
// latitude and longitude and the direction of the terrain's grid north
// (+y) from true north. A geographic DEM's grid north is true north; a
// projected one's (UTM) differs by the meridian convergence, up to about
// 3 deg at a UTM zone's edge at 45 deg latitude, which the sun's direction
// is rotated by. No GL.

#include <memory>
#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "terrain/heightfield.h"

namespace ig::environment {

struct GeoLocation {
  double latitude_deg = 0.0;
  double longitude_deg = 0.0;
  // Azimuth of grid +y, clockwise from true north (deg).
  double grid_north_deg = 0.0;
};

class TerrainGeolocation {
 public:
  // nullptr when the heightfield has no georeference or its CRS cannot be
  // transformed to WGS84.
  static std::unique_ptr<TerrainGeolocation> make(const terrain::Heightfield& hf);
  ~TerrainGeolocation();

  // The point at terrain-local (x, y) metres (heightfield.h: sample (i, j) at
  // (i spacing_x, j spacing_y)); nullopt when the transform fails there.
  std::optional<GeoLocation> locate(glm::dvec2 local_xy) const;

 private:
  struct Impl;
  explicit TerrainGeolocation(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// A direction towards the sun in terrain-local axes from its true azimuth
// (clockwise from true north) and elevation; and back.
glm::dvec3 local_direction(double azimuth_deg, double elevation_deg, double grid_north_deg);
struct SunAngles {
  double elevation_deg = 0.0;
  double azimuth_deg = 0.0;  // clockwise from true north, [0, 360)
};
SunAngles angles_of(const glm::dvec3& local_direction, double grid_north_deg);

}  // namespace ig::environment
