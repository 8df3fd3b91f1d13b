#include "terrain/georef.h"

#include "terrain/dem_loader.h"

#include <ogr_spatialref.h>

#include <cmath>
#include <memory>

namespace ig::terrain {

namespace {

// WGS84 longitude/latitude to the DEM's CRS (to_dem), or back; null when
// the DEM's CRS cannot be read or no transformation exists.
std::unique_ptr<OGRCoordinateTransformation> wgs84_transform(const GeoReference& georef, bool to_dem) {
  OGRSpatialReference wgs84, dem;
  wgs84.SetWellKnownGeogCS("WGS84");
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);  // x = lon, y = lat
  if (dem.importFromWkt(georef.crs_wkt.c_str()) != OGRERR_NONE) return nullptr;
  dem.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  return std::unique_ptr<OGRCoordinateTransformation>(
      to_dem ? OGRCreateCoordinateTransformation(&wgs84, &dem) : OGRCreateCoordinateTransformation(&dem, &wgs84));
}

}  // namespace

std::optional<glm::dvec2> geodetic_to_local(const Heightfield& hf, double lat_deg, double lon_deg) {
  if (!hf.georef || !std::isfinite(lat_deg) || !std::isfinite(lon_deg)) return std::nullopt;
  const auto ct = wgs84_transform(*hf.georef, true);
  if (!ct) return std::nullopt;
  double x = lon_deg, y = lat_deg;
  if (!ct->Transform(1, &x, &y)) return std::nullopt;
  // Invert the affine grid (i, j) -> CRS map.
  const auto& g = hf.georef->grid_to_crs;
  const double det = g[1] * g[5] - g[2] * g[4];
  if (det == 0.0) return std::nullopt;
  const double dx = x - g[0], dy = y - g[3];
  const double i = (g[5] * dx - g[2] * dy) / det;
  const double j = (-g[4] * dx + g[1] * dy) / det;
  return glm::dvec2(i * hf.spacing_x_m, j * hf.spacing_y_m);
}

std::optional<glm::dvec2> local_to_geodetic(const Heightfield& hf, double x_m, double y_m) {
  if (!hf.georef || !std::isfinite(x_m) || !std::isfinite(y_m)) return std::nullopt;
  const auto ct = wgs84_transform(*hf.georef, false);
  if (!ct) return std::nullopt;
  const auto& g = hf.georef->grid_to_crs;
  const double i = x_m / hf.spacing_x_m, j = y_m / hf.spacing_y_m;
  double x = g[0] + i * g[1] + j * g[2], y = g[3] + i * g[4] + j * g[5];
  if (!ct->Transform(1, &x, &y) || !std::isfinite(x) || !std::isfinite(y)) return std::nullopt;
  return glm::dvec2(y, x);
}

GeoReference make_geographic_georef(double lat0_deg, double lon0_deg, double spacing_x_m, double spacing_y_m) {
  OGRSpatialReference wgs84;
  wgs84.SetWellKnownGeogCS("WGS84");
  char* wkt = nullptr;
  wgs84.exportToWkt(&wkt);
  GeoReference g;
  g.crs_wkt = wkt ? wkt : "";
  CPLFree(wkt);
  g.crs_name = "EPSG:4326";
  g.geographic = true;
  const MetresPerAngle m = metres_per_angle(lat0_deg);
  // (i, j) -> (lon, lat): GDAL-style affine for our south-up sample indices.
  g.grid_to_crs = {lon0_deg, spacing_x_m / m.east, 0.0, lat0_deg, 0.0, spacing_y_m / m.north};
  return g;
}

}  // namespace ig::terrain
