#pragma once
// E: where the view's centre ray meets the terrain (exact ray cast), the
// point Level1 is centred on. When the ray misses (sky, over the DEM's edge)
// E falls back to a continuous, bounded choice, never a point at infinity:
// the flat-ground intersection of the ray at the eye's height above the
// terrain below it, at most fallback_distance_m away horizontally along the
// view's horizontal direction, clamped onto the DEM, at surface height.

#include <glm/vec3.hpp>

#include "terrain/height_pyramid.h"
#include "terrain/heightfield.h"

namespace ig::lod {

struct LookAtPoint {
  glm::dvec3 point{0.0};  // terrain-local metres, on the surface
  bool hit = false;       // true: exact ray hit; false: fallback
};

// horizontal_hint: a horizontal-ish direction to use when dir is vertical
// (e.g. the camera's up vector when looking straight down).
LookAtPoint find_look_at_point(const terrain::Heightfield& hf, const terrain::HeightPyramid& pyramid,
                               const glm::dvec3& eye, const glm::dvec3& dir, const glm::dvec3& horizontal_hint,
                               double fallback_distance_m);

}  // namespace ig::lod
