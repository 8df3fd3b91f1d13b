#pragma once
// Placing geodetic (WGS84 lat/lon) positions on a georeferenced heightfield.

#include <optional>

#include <glm/vec2.hpp>

#include "terrain/heightfield.h"

namespace ig::terrain {

// Local x/y metres (see heightfield.h) of a WGS84 latitude/longitude, through
// the DEM's own CRS and grid. nullopt when the heightfield has no georeference
// or the transform fails. Local = grid index * spacing, so geographic DEMs use
// the grid's own (centre-latitude) spacing, consistent with the rendered mesh.
std::optional<glm::dvec2> geodetic_to_local(const Heightfield& hf, double lat_deg, double lon_deg);

// The inverse: WGS84 (lat_deg, lon_deg) of local x/y metres, for geographic
// and projected DEMs alike (through GDAL/OGR: for messages, not per frame).
// nullopt without a georeference or when the transform fails.
std::optional<glm::dvec2> local_to_geodetic(const Heightfield& hf, double x_m, double y_m);

// A WGS84 geographic georeference for a grid whose south-west sample sits at
// (lat0, lon0) with the given ground spacing (degrees per sample from the
// ellipsoid at lat0): lets generated terrain take geodetic poses (CIGI,
// FlightGear) like a real DEM.
GeoReference make_geographic_georef(double lat0_deg, double lon0_deg, double spacing_x_m, double spacing_y_m);

}  // namespace ig::terrain
