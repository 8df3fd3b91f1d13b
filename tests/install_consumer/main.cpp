// Uses the installed libraries the way an integrator would: generate a
// terrain, build the two-level method's Level0 over it, cast a ray, and
// round-trip a native pose datagram. Prints one line per check.
#include <cstdio>

#include "io/wire/native.h"
#include "lod/roam_level0_mesh.h"
#include "terrain/height_pyramid.h"
#include "terrain/ray_cast.h"
#include "terrain/synthetic_terrain.h"

int main() {
  ig::options::SyntheticTerrainOptions p;
  p.size = 129;
  const auto hf = ig::terrain::generate_synthetic_terrain(p);
  const auto level0 = ig::lod::build_level0_mesh(hf, {512});
  const ig::terrain::HeightPyramid pyramid(hf);
  const auto hit = ig::terrain::cast_ray(hf, pyramid, {100.0, 100.0, hf.max_m + 100.0}, {0.6, 0.6, -0.5});
  ig::io::wire::PoseMessage pose;
  pose.position = {1.0, 2.0, 3.0};
  const auto bytes = ig::io::wire::encode_native(pose);
  const auto back = ig::io::wire::decode_native(bytes);
  std::printf("terrain %dx%d level0 %d triangles ray %s native %s\n", hf.width, hf.height, level0.triangle_count,
              hit ? "hit" : "miss", back.ok() ? "ok" : "bad");
  return level0.triangle_count > 0 && hit && back.ok() ? 0 : 1;
}
