#include "render/scene_level0.h"

namespace ig::render {

lod::Level0Mesh build_scene_level0(const TerrainScene& scene, const lod::Level0Options& options) {
  lod::Level0Mesh mesh = lod::build_level0_mesh(scene.texture_heightfield(), options);
  const int step = scene.overview_step();
  if (step == 1) return mesh;
  // Overview sample (k, l) is DEM sample (k, l) * step: positions as the
  // DEM's own sample positions (the same rounding as a mesh built on it).
  const auto& hf = scene.heightfield();
  for (std::size_t v = 0; v < mesh.samples.size(); ++v) {
    mesh.samples[v] *= step;
    mesh.positions[v].x = float(mesh.samples[v].x * hf.spacing_x_m);
    mesh.positions[v].y = float(mesh.samples[v].y * hf.spacing_y_m);
  }
  return mesh;
}

}  // namespace ig::render
