#pragma once
// A conservative upper envelope for the static Level0 mesh: each
// vertex is lifted so that no triangle passes below any DEM sample it
// covers. A coarse Level0 then never cuts a ridge below the true skyline
// (no sky through terrain); its remaining error is upwards only, at most
// the largest lift. No GL.
//
// For each triangle t: d_t = max over the samples s inside it of
// (h(s) - plane_t(s)), at least 0, plus the chord's sag below the Earth's
// curve (L^2 / 8R over its longest edge) when the scene is curved. Each
// vertex is lifted by the largest d_t of its triangles; a barycentric mix of
// lifts each >= d_t is >= d_t, so every covered sample lies on or below the
// lifted triangle. One pass over the samples (each lies in one or two
// triangles): about 0.1 s for 4097^2.

#include <vector>

#include "lod/roam_level0_mesh.h"
#include "terrain/heightfield.h"

namespace ig::lod {

struct Level0Envelope {
  std::vector<float> lift_m;    // per vertex of the mesh, >= 0
  double max_lift_m = 0.0;
  double max_cut_m = 0.0;       // the largest d_t: how far the plain mesh cut below a sample
};

Level0Envelope level0_upper_envelope(const Level0Mesh& mesh, const terrain::Heightfield& hf,
                                     double earth_radius_m = 0.0);

}  // namespace ig::lod
