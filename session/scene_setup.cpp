#include "session/scene_setup.h"

#include <algorithm>
#include <string>

#include "io/filter/geodesy.h"
#include "terrain/dem_loader.h"
#include "terrain/earth_curvature.h"
#include "terrain/georef.h"
#include "terrain/synthetic_terrain.h"
#include "water/water_setup.h"

namespace ig::session {

terrain::Heightfield load_terrain(const io::TerrainSpec& spec) {
  terrain::Heightfield hf;
  if (spec.generator) {
    const auto& g = *spec.generator;
    hf = terrain::generate_synthetic_terrain(g);
    if (g.origin_lat_lon)
      hf.georef = terrain::make_geographic_georef((*g.origin_lat_lon)[0], (*g.origin_lat_lon)[1], hf.spacing_x_m,
                                                  hf.spacing_y_m);
  } else {
    hf = terrain::load_dem(*spec.file, spec);  // its DemLoadOptions part
  }
  water::place_water(hf, spec.water);
  return hf;
}

io::PathSpec place_path(const io::PathSpec& path, const terrain::Heightfield& hf) {
  io::PathSpec out = path;
  out.frame = io::PositionFrame::Local;
  out.altitude = io::AltitudeMode::AboveSeaLevel;
  for (size_t k = 0; k < out.keys.size(); ++k) {
    auto& p = out.keys[k].position;
    const std::string where = "path.keys[" + std::to_string(k) + "].position";
    if (path.frame == io::PositionFrame::Geodetic) {
      if (!hf.georef)
        throw io::ScenarioError(where + ": geodetic position but the terrain (" + hf.source +
                                ") has no georeference; use \"frame\": \"local\"");
      const auto xy = terrain::geodetic_to_local(hf, p[0], p[1]);
      if (!xy) throw io::ScenarioError(where + ": cannot transform lat/lon into the DEM's CRS");
      p = {xy->x, xy->y, p[2]};
    }
    if (path.altitude == io::AltitudeMode::AboveGround) p[2] += hf.sample_surface(p[0], p[1]);
  }
  return out;
}

double earth_radius_for(const io::RenderSpec& render, const io::TerrainSpec& spec, const terrain::Heightfield& hf) {
  if (render.earth_curvature == "on") return terrain::kEarthRadiusM;
  if (render.earth_curvature == "off") return 0.0;
  const double span = std::max(hf.extent_x_m(), hf.extent_y_m());
  return spec.file && hf.georef && span > kAutoCurvatureSpanM ? terrain::kEarthRadiusM : 0.0;
}

io::GeodeticToLocal geodetic_placer(const terrain::Heightfield& hf) {
  if (!hf.georef) return nullptr;
  if (hf.georef->geographic) {
    const auto grid = io::geo::GeographicGrid::make(hf.georef->grid_to_crs, hf.spacing_x_m, hf.spacing_y_m);
    if (!grid) return nullptr;
    return [grid = *grid](double lat, double lon, double alt) -> std::optional<glm::dvec3> {
      const glm::dvec2 xy = grid.to_local(lat, lon);
      return glm::dvec3(xy, alt);
    };
  }
  return [&hf](double lat, double lon, double alt) -> std::optional<glm::dvec3> {
    const auto xy = terrain::geodetic_to_local(hf, lat, lon);
    if (!xy) return std::nullopt;
    return glm::dvec3(*xy, alt);
  };
}

std::function<std::optional<glm::dvec3>(const glm::dvec3&)> local_to_geodetic(const terrain::Heightfield& hf) {
  if (!hf.georef || !hf.georef->geographic) return nullptr;  // projected DEMs: senders use local frames
  const auto grid = io::geo::GeographicGrid::make(hf.georef->grid_to_crs, hf.spacing_x_m, hf.spacing_y_m);
  if (!grid) return nullptr;
  return [grid = *grid](const glm::dvec3& local) -> std::optional<glm::dvec3> {
    const auto g = grid.from_local(local);
    return glm::dvec3(g.lat_deg, g.lon_deg, g.height_m);
  };
}

}  // namespace ig::session
