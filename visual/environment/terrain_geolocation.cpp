#include "environment/terrain_geolocation.h"

#include <ogr_spatialref.h>

#include <cmath>

#include "terrain/dem_loader.h"

namespace ig::environment {
namespace {
constexpr double kDegToRad = 0.017453292519943295;

// Distance along grid +y over which grid north is measured: short enough to
// be local, long enough for the transform's rounding not to matter.
constexpr double kNorthProbeM = 100.0;

struct TransformDeleter {
  void operator()(OGRCoordinateTransformation* t) const { OGRCoordinateTransformation::DestroyCT(t); }
};
}  // namespace

struct TerrainGeolocation::Impl {
  std::array<double, 6> grid_to_crs{};
  double spacing_x_m = 1.0, spacing_y_m = 1.0;
  // CRS -> WGS84 lon/lat; null for a geographic CRS (its x, y are lon, lat).
  std::unique_ptr<OGRCoordinateTransformation, TransformDeleter> to_wgs84;

  // (lat, lon) of terrain-local (x, y).
  std::optional<glm::dvec2> lat_lon(glm::dvec2 xy) const {
    const double i = xy.x / spacing_x_m, j = xy.y / spacing_y_m;
    const auto& g = grid_to_crs;
    double x = g[0] + g[1] * i + g[2] * j;
    double y = g[3] + g[4] * i + g[5] * j;
    if (to_wgs84 && !to_wgs84->Transform(1, &x, &y)) return std::nullopt;
    if (!std::isfinite(x) || !std::isfinite(y)) return std::nullopt;
    return glm::dvec2(y, x);
  }
};

TerrainGeolocation::TerrainGeolocation(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
TerrainGeolocation::~TerrainGeolocation() = default;

std::unique_ptr<TerrainGeolocation> TerrainGeolocation::make(const terrain::Heightfield& hf) {
  if (!hf.georef || !(hf.spacing_x_m > 0.0) || !(hf.spacing_y_m > 0.0)) return nullptr;
  auto impl = std::make_unique<Impl>();
  impl->grid_to_crs = hf.georef->grid_to_crs;
  impl->spacing_x_m = hf.spacing_x_m;
  impl->spacing_y_m = hf.spacing_y_m;
  if (!hf.georef->geographic) {
    OGRSpatialReference dem, wgs84;
    if (dem.importFromWkt(hf.georef->crs_wkt.c_str()) != OGRERR_NONE) return nullptr;
    dem.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);  // x = lon, y = lat
    impl->to_wgs84.reset(OGRCreateCoordinateTransformation(&dem, &wgs84));
    if (!impl->to_wgs84) return nullptr;
  }
  return std::unique_ptr<TerrainGeolocation>(new TerrainGeolocation(std::move(impl)));
}

std::optional<GeoLocation> TerrainGeolocation::locate(glm::dvec2 xy) const {
  const auto here = impl_->lat_lon(xy);
  const auto north = impl_->lat_lon(xy + glm::dvec2(0.0, kNorthProbeM));
  if (!here || !north) return std::nullopt;
  GeoLocation g;
  g.latitude_deg = here->x;
  g.longitude_deg = std::remainder(here->y, 360.0);
  const terrain::MetresPerAngle m = terrain::metres_per_angle(g.latitude_deg);
  const double east_m = std::remainder(north->y - here->y, 360.0) * m.east;
  const double north_m = (north->x - here->x) * m.north;
  g.grid_north_deg = std::atan2(east_m, north_m) / kDegToRad;
  return g;
}

glm::dvec3 local_direction(double azimuth_deg, double elevation_deg, double grid_north_deg) {
  const double a = (azimuth_deg - grid_north_deg) * kDegToRad, e = elevation_deg * kDegToRad;
  return {std::sin(a) * std::cos(e), std::cos(a) * std::cos(e), std::sin(e)};
}

SunAngles angles_of(const glm::dvec3& d, double grid_north_deg) {
  SunAngles s;
  const double horizontal = std::hypot(d.x, d.y);
  s.elevation_deg = std::atan2(d.z, horizontal) / kDegToRad;
  double az = std::atan2(d.x, d.y) / kDegToRad + grid_north_deg;
  az = std::fmod(az, 360.0);
  if (az < 0.0) az += 360.0;
  s.azimuth_deg = az;
  return s;
}

}  // namespace ig::environment
