#pragma once
// WGS84 geodesy in double precision (GeographicLib's Geocentric and
// Ellipsoid, no GDAL): the fast path for per-packet pose intake at 60 Hz and
// more (the per-pose conversions do not allocate).
//
//   geodetic (lat, lon, h)  <->  ECEF (earth-centred, earth-fixed, metres)
//   ECEF                    <->  local ENU (east, north, up) at a reference point
//   geodetic                 ->  terrain-local metres on a geographic (lat/lon
//                               degree) DEM grid, matching the Heightfield's
//                               convention and terrain::geodetic_to_local.
//
// Angles are degrees at the API, heights are metres above the WGS84
// ellipsoid. Projected DEM CRSs (UTM, ...) stay on the OGR path in
// visual/terrain/georef.h; see docs/pose-filter.md, "Geodesy".

#include <array>
#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ig::io::geo {

// WGS84 defining constants and derived values.
inline constexpr double kWgs84A = 6378137.0;                  // semi-major axis, m
inline constexpr double kWgs84InvF = 298.257223563;           // inverse flattening
inline constexpr double kWgs84F = 1.0 / kWgs84InvF;
inline constexpr double kWgs84B = kWgs84A * (1.0 - kWgs84F);  // semi-minor, 6356752.314245 m
inline constexpr double kWgs84E2 = kWgs84F * (2.0 - kWgs84F);  // first eccentricity squared

struct Geodetic {
  double lat_deg = 0.0;  // [-90, 90], north positive
  double lon_deg = 0.0;  // east positive; any value in, (-180, 180] out
  double height_m = 0.0;  // above the ellipsoid (not the geoid / MSL)
};

glm::dvec3 geodetic_to_ecef(const Geodetic& g);
// GeographicLib's closed-form inversion (accurate to about 1e-9 m for all
// terrestrial and orbital heights); longitude in (-180, 180], 0 at the poles.
Geodetic ecef_to_geodetic(const glm::dvec3& ecef);

// Local east-north-up tangent frame at a reference point. Construct once per
// reference; the conversions are a handful of multiply-adds.
class EnuFrame {
 public:
  explicit EnuFrame(const Geodetic& origin);
  const Geodetic& origin() const { return origin_; }
  const glm::dvec3& origin_ecef() const { return origin_ecef_; }

  glm::dvec3 ecef_to_enu(const glm::dvec3& ecef) const;
  glm::dvec3 enu_to_ecef(const glm::dvec3& enu) const;
  glm::dvec3 geodetic_to_enu(const Geodetic& g) const { return ecef_to_enu(geodetic_to_ecef(g)); }
  Geodetic enu_to_geodetic(const glm::dvec3& enu) const { return ecef_to_geodetic(enu_to_ecef(enu)); }
  // Rotate a direction (velocity, ...) between the frames, no translation.
  glm::dvec3 ecef_dir_to_enu(const glm::dvec3& d) const;
  glm::dvec3 enu_dir_to_ecef(const glm::dvec3& d) const;

 private:
  Geodetic origin_;
  glm::dvec3 origin_ecef_{0.0};
  glm::dvec3 east_{1, 0, 0}, north_{0, 1, 0}, up_{0, 0, 1};  // unit axes in ECEF
};

// Metres per degree along the meridian / the parallel of the WGS84 ellipsoid
// at a latitude (GeographicLib's radii of curvature, as the DEM loader's
// terrain::metres_per_angle for geographic rasters).
struct MetresPerDegree {
  double north = 0.0;  // meridian radius * pi/180
  double east = 0.0;   // prime-vertical radius * cos(lat) * pi/180
};
MetresPerDegree metres_per_degree(double lat_deg);

// A geographic (lon/lat degree, WGS84) DEM grid as loaded into a Heightfield:
// sample (i, j) (row j = 0 south) sits at CRS (x = lon, y = lat) =
//   (g[0] + i*g[1] + j*g[2],  g[3] + i*g[4] + j*g[5])      (GeoReference::grid_to_crs)
// and at local metres (i * spacing_x_m, j * spacing_y_m), the spacings being
// the ground distance of one grid step at the DEM's centre latitude
// (Heightfield::spacing_x_m / spacing_y_m). Build it once per DEM with
// make(...), then place poses with to_local(...).
class GeographicGrid {
 public:
  // nullopt when the affine map is singular or anything is not finite or the
  // spacings are not positive.
  static std::optional<GeographicGrid> make(const std::array<double, 6>& grid_to_crs,
                                            double spacing_x_m, double spacing_y_m);

  // Terrain-local (x, y) metres of a latitude/longitude. Longitude is unwrapped
  // to within +-180 deg of sample (0, 0)'s, so grids across the antimeridian
  // work. Otherwise the same as terrain::geodetic_to_local for an EPSG:4326
  // DEM (to ~1e-9 m), without OGR and without allocating.
  glm::dvec2 to_local(double lat_deg, double lon_deg) const;
  // (x, y) as above, z = the given height unchanged (ellipsoidal height; no
  // geoid applied, see docs).
  glm::dvec3 to_local(const Geodetic& g) const;
  // Inverse of to_local (x, y -> lat, lon; z -> height).
  Geodetic from_local(const glm::dvec3& local) const;
  // Fractional sample index (i, j) of a latitude/longitude.
  glm::dvec2 to_index(double lat_deg, double lon_deg) const;

  const std::array<double, 6>& grid_to_crs() const { return g_; }
  double spacing_x_m() const { return sx_; }
  double spacing_y_m() const { return sy_; }

 private:
  std::array<double, 6> g_{};
  double sx_ = 1.0, sy_ = 1.0;
  // Inverse of the 2x2 part of g_.
  double inv00_ = 1.0, inv01_ = 0.0, inv10_ = 0.0, inv11_ = 1.0;
  double ref_lon_ = 0.0;  // longitude of sample (0, 0), for unwrapping
};

}  // namespace ig::io::geo
