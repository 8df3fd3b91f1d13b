#pragma once
// The two-level method's Level0 for a scene: built on what the scene's
// height texture holds (the DEM, or beyond the GL texture limit its overview,
// terrain/heightfield_overview.h), with sample indices and positions given
// in the DEM's own samples, so Level0's vertices are DEM samples either way
// (e.g. a 20481^2 DEM's Level0 is built on a 4097^2 overview).

#include "lod/roam_level0_mesh.h"
#include "render/terrain_scene.h"

namespace ig::render {

lod::Level0Mesh build_scene_level0(const TerrainScene& scene, const lod::Level0Options& options);

}  // namespace ig::render
