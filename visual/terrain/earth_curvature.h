#pragma once
// Earth curvature for georeferenced terrain: the DEM is a flat grid, but the
// renderer lowers every point by the drop of a sphere of radius R below the
// eye's tangent plane, d horizontal metres from the eye:
//   drop(d) = R - sqrt(R^2 - d^2) = d^2 / (R + sqrt(R^2 - d^2))   (~ d^2 / 2R)
// The second form has no cancellation, so it holds in float on the GPU
// (shaders/*.vert) as well as in double here. Horizontal positions are kept
// (vertical projection onto the sphere): the grid's own metres stay exact
// under the eye, where the detail is. R <= 0 means a flat world (no drop).

#include <algorithm>
#include <cmath>

namespace ig::terrain {

// Mean Earth radius (IUGG), metres.
constexpr double kEarthRadiusM = 6371008.8;

// The drop from the squared horizontal distance d^2 (clamped to R^2: the
// sphere's widest point). Inner loops (the ray cast) pass dx^2 + dy^2: no
// hypot to take first.
inline double curvature_drop_squared(double d2, double earth_radius_m) {
  if (!(earth_radius_m > 0.0)) return 0.0;
  d2 = std::min(d2, earth_radius_m * earth_radius_m);
  return d2 / (earth_radius_m + std::sqrt(earth_radius_m * earth_radius_m - d2));
}

// The drop at horizontal distance d.
inline double curvature_drop(double horizontal_distance_m, double earth_radius_m) {
  return curvature_drop_squared(horizontal_distance_m * horizontal_distance_m, earth_radius_m);
}

}  // namespace ig::terrain
