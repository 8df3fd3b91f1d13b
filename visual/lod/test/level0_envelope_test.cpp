// The Level0 upper envelope (lod/level0_envelope.h): after lifting, no DEM
// sample lies above the triangle that covers it, on generated terrain at
// several budgets and on a non-(2^n+1) DEM; lifts are zero where the mesh
// already lies on or above the samples.
#include "lod/level0_envelope.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include <glm/common.hpp>

#include "lod/roam_level0_mesh.h"
#include "terrain/synthetic_terrain.h"

namespace {
using ig::lod::Level0Mesh;

// Largest (sample - lifted surface) over every sample inside every triangle.
double worst_sample_above(const Level0Mesh& m, const std::vector<float>& lift, const ig::terrain::Heightfield& hf) {
  double worst = -1e30;
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const auto ia = m.indices[t], ib = m.indices[t + 1], ic = m.indices[t + 2];
    const glm::ivec2 a = m.samples[ia], b = m.samples[ib], c = m.samples[ic];
    const double ha = hf.at(a.x, a.y) + lift[ia], hb = hf.at(b.x, b.y) + lift[ib], hc = hf.at(c.x, c.y) + lift[ic];
    const double den = double(b.y - c.y) * (a.x - c.x) + double(c.x - b.x) * (a.y - c.y);
    const glm::ivec2 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    for (int j = lo.y; j <= hi.y; ++j)
      for (int i = lo.x; i <= hi.x; ++i) {
        const double wa = (double(b.y - c.y) * (i - c.x) + double(c.x - b.x) * (j - c.y)) / den;
        const double wb = (double(c.y - a.y) * (i - c.x) + double(a.x - c.x) * (j - c.y)) / den;
        const double wc = 1.0 - wa - wb;
        if (wa < -1e-9 || wb < -1e-9 || wc < -1e-9) continue;
        worst = std::max(worst, double(hf.at(i, j)) - (wa * ha + wb * hb + wc * hc));
      }
  }
  return worst;
}
}  // namespace

TEST(Level0Envelope, NoSampleAboveTheLiftedMesh) {
  for (int size : {129, 257, 200}) {
    ig::options::SyntheticTerrainOptions p;
    p.size = size == 200 ? 257 : size;
    p.seed = 11;
    auto hf = ig::terrain::generate_synthetic_terrain(p);
    if (size == 200) {  // crop to a non-(2^n+1) DEM
      ig::terrain::Heightfield c = hf;
      c.width = c.height = 200;
      c.heights.resize(200 * 200);
      for (int j = 0; j < 200; ++j)
        for (int i = 0; i < 200; ++i) c.heights[size_t(j) * 200 + i] = hf.at(i, j);
      hf = c;
    }
    for (int budget : {64, 512, 4096}) {
      const Level0Mesh m = ig::lod::build_level0_mesh(hf, {budget, 0.0});
      const std::vector<float> none(m.samples.size(), 0.0f);
      const auto env = ig::lod::level0_upper_envelope(m, hf);
      const double before = worst_sample_above(m, none, hf), after = worst_sample_above(m, env.lift_m, hf);
      std::printf("[envelope] %dx%d, %d triangles: samples up to %.2f m above the mesh, %.4f m after lifting "
                  "(max lift %.2f m)\n", hf.width, hf.height, m.triangle_count, before, after, env.max_lift_m);
      EXPECT_GT(before, 0.0);  // the plain mesh cuts below some samples
      EXPECT_LE(after, 1e-3);  // the lifted one never does
      EXPECT_NEAR(env.max_cut_m, before, 1e-3);
      EXPECT_LE(env.max_lift_m, env.max_cut_m + 0.02);
    }
  }
}

TEST(Level0Envelope, FlatGroundNeedsNoLiftUnlessCurved) {
  ig::terrain::Heightfield hf;
  hf.width = hf.height = 65;
  hf.spacing_x_m = hf.spacing_y_m = 1000.0;
  hf.heights.assign(65 * 65, 100.0f);
  const Level0Mesh m = ig::lod::build_level0_mesh(hf, {32, 0.0});
  EXPECT_EQ(ig::lod::level0_upper_envelope(m, hf).max_lift_m, 0.0);
  // On a 6371 km sphere a 45 km chord sags 40 m below the curve.
  const auto curved = ig::lod::level0_upper_envelope(m, hf, 6371000.0);
  EXPECT_GT(curved.max_lift_m, 1.0);
}
