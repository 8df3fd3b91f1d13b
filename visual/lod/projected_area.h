#pragma once
// Screen area of a planar polygon, for the paper's "projected area" ratio of
// the two levels (bench_twolevel's Table 1): unlike the visible-pixel ratio
// the size controller uses, it counts what is hidden behind nearer terrain.
// No GL: the polygon is clipped in homogeneous clip space (near plane and
// the four sides) and its area taken with the shoelace formula.

#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace ig::lod {

// Pixels covered by the convex or concave planar polygon `corners`
// (eye-relative world coordinates, in order) seen through `view_proj` on a
// width x height viewport; 0 when it is wholly outside the view.
double projected_area_px(const glm::dmat4& view_proj, const std::vector<glm::dvec3>& corners, int width,
                         int height);

}  // namespace ig::lod
