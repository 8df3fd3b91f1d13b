#pragma once
// Turning a scenario's declarative parts into things the IG can use: the
// heightfield (file or generator) with its water and the ownship path in terrain-local
// metres above sea level.

#include <functional>
#include <optional>

#include <glm/vec3.hpp>

#include "io/pose_intake.h"
#include "io/scenario.h"
#include "terrain/heightfield.h"

namespace ig::session {

// The heightfield with its water (terrain.water, water/water_setup.h). Throws
// terrain::DemError / water::WaterFileError / std::invalid_argument with a
// one-line reason.
terrain::Heightfield load_terrain(const io::TerrainSpec& spec);

// Keys converted to local ENU metres above sea level: geodetic keys through
// the DEM's georeference (error when it has none), AGL altitudes on top of
// the surface under each key. Throws io::ScenarioError naming the key.
io::PathSpec place_path(const io::PathSpec& path, const terrain::Heightfield& hf);

// The Earth radius the scene is drawn with (0 = flat) for render.earth_curvature:
// "on" -> terrain::kEarthRadiusM, "off" -> 0, "auto" -> on for a DEM file that
// is georeferenced and whose larger side exceeds kAutoCurvatureSpanM (the drop
// is 0.5 m at 2.5 km from the eye, 2 m at 5 km: below that it is lost in the
// DEM's own error). Generated terrain stays flat under "auto": it is a
// synthetic world (its origin only places geodetic poses on it).
constexpr double kAutoCurvatureSpanM = 5000.0;
double earth_radius_for(const io::RenderSpec& render, const io::TerrainSpec& terrain, const terrain::Heightfield& hf);

// Geodetic -> terrain-local placement for pose packets: the allocation-free
// WGS84 grid path for geographic DEMs, GDAL/OGR for projected ones, and
// nullopt for every packet when the terrain has no georeference.
io::GeodeticToLocal geodetic_placer(const terrain::Heightfield& hf);
// The inverse, for senders (local ENU -> lat deg, lon deg, alt m).
std::function<std::optional<glm::dvec3>(const glm::dvec3&)> local_to_geodetic(const terrain::Heightfield& hf);

}  // namespace ig::session
