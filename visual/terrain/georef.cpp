#include "terrain/georef.h"

#include <ogr_spatialref.h>

#include <cmath>
#include <memory>

namespace ig::terrain {

std::optional<glm::dvec2> geodetic_to_local(const Heightfield& hf, double lat_deg, double lon_deg) {
  if (!hf.georef || !std::isfinite(lat_deg) || !std::isfinite(lon_deg)) return std::nullopt;
  OGRSpatialReference wgs84, dem;
  wgs84.SetWellKnownGeogCS("WGS84");
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);  // x = lon, y = lat
  if (dem.importFromWkt(hf.georef->crs_wkt.c_str()) != OGRERR_NONE) return std::nullopt;
  dem.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&wgs84, &dem));
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

}  // namespace ig::terrain
