#pragma once
// E: where the view's centre ray meets the terrain (exact ray cast), the
// point Level1 is centred on. When the ray misses (sky, over the DEM's edge)
// E falls back to the terrain point nearest the ray in angle within the
// vertical plane of the view: the point of greatest elevation angle, seen
// from the eye, along the DEM profile under the view's horizontal direction
// (the visible horizon in that direction). A ray hits exactly when its
// elevation is at most that angle, and at the switch it touches the terrain
// at that very point, so E is continuous across hit <-> miss both ways (up
// to ties between equally high horizon points). When the view's horizontal
// line misses the DEM altogether, E is the DEM point nearest that line
// (which is where the profile begins when the line starts to touch it).
// Always finite, on the DEM, at surface height; never a point at infinity.
//
// Earth curvature (earth_radius_m > 0): the renderer lowers the terrain by
// the sphere's drop below the eye (terrain/earth_curvature.h). The ray cast
// and the horizon search use the same drop, taken linear between knots every
// kCurvatureKnotM of horizontal distance from the eye (vertical error at most
// kCurvatureKnotM^2 / (8 R) = 0.08 m), so both agree with each other exactly
// and with the image within that bound.

#include <glm/vec3.hpp>

#include "terrain/height_pyramid.h"
#include "terrain/heightfield.h"

namespace ig::lod {

struct LookAtPoint {
  glm::dvec3 point{0.0};  // terrain-local metres, on the surface
  bool hit = false;       // true: exact ray hit; false: fallback
};

// Knot spacing of the piecewise-linear curvature drop, metres.
constexpr double kCurvatureKnotM = 2000.0;

// eye and dir in terrain-local metres (dir need not be normalised).
// horizontal_hint: the camera's up vector; used when dir is vertical, so the
// fallback stays continuous when pitching through +-90 degrees (looking up,
// the view's horizontal direction tends to -up; looking down, to +up).
LookAtPoint find_look_at_point(const terrain::Heightfield& hf, const terrain::HeightPyramid& pyramid,
                               const glm::dvec3& eye, const glm::dvec3& dir, const glm::dvec3& horizontal_hint,
                               double earth_radius_m = 0.0);

}  // namespace ig::lod
