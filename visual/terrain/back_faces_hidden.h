#pragma once
// Whether terrain faces turned away from the eye can be skipped (back-face
// culling) without changing the picture.
//
// A heightfield has no overhangs: seen from a point above its surface, a ray
// reaches the surface from above, i.e. through a face turned towards the eye,
// before it could reach any face turned away. So while the eye is above the
// surface, every back face is hidden. An eye under the surface (flown into a
// hill, or a host's bad altitude) sees back faces, and culling them would
// show it sky instead of the terrain's underside.
//
// "Above" is judged conservatively: above the highest corner of the grid cell
// under the eye, or above the highest sample when the eye is outside the
// grid. A coarse LOD mesh that bulges above a very low eye is not covered;
// that eye is inside drawn terrain either way.

#include <glm/vec3.hpp>

#include "terrain/heightfield.h"

namespace ig::terrain {

// local_eye: terrain-local metres (sample (0, 0) at the origin).
bool back_faces_hidden(const Heightfield& hf, const glm::dvec3& local_eye);

}  // namespace ig::terrain
