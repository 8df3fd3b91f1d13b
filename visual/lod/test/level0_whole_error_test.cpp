// Level0 built on whole-triangle error (Level0Options::whole_triangle_error):
// max_error_m then bounds the vertical distance of every DEM sample from the
// mesh; the nested midpoint error (the default) does not promise that.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "lod/roam_level0_mesh.h"
#include "lod_test_terrain.h"

namespace {

// Largest |sample - mesh| over all samples, each measured on the mesh triangle covering it.
double worst_sample_error(const ig::terrain::Heightfield& hf, const ig::lod::Level0Mesh& m) {
  double worst = 0.0;
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const glm::ivec2 a = m.samples[m.indices[t]], b = m.samples[m.indices[t + 1]], c = m.samples[m.indices[t + 2]];
    const double ha = hf.at(a.x, a.y), hb = hf.at(b.x, b.y), hc = hf.at(c.x, c.y);
    const double det = double(b.x - a.x) * (c.y - a.y) - double(c.x - a.x) * (b.y - a.y);
    for (int j = std::min({a.y, b.y, c.y}); j <= std::max({a.y, b.y, c.y}); ++j)
      for (int i = std::min({a.x, b.x, c.x}); i <= std::max({a.x, b.x, c.x}); ++i) {
        const double u = (double(i - a.x) * (c.y - a.y) - double(c.x - a.x) * (j - a.y)) / det;
        const double v = (double(b.x - a.x) * (j - a.y) - double(i - a.x) * (b.y - a.y)) / det;
        if (u < -1e-9 || v < -1e-9 || u + v > 1 + 1e-9) continue;
        worst = std::max(worst, std::abs(hf.at(i, j) - (ha + u * (hb - ha) + v * (hc - ha))));
      }
  }
  return worst;
}

TEST(Level0WholeTriangleError, MaxErrorBoundsEverySample) {
  const auto hf = lod_checks::synthetic(257);
  for (int budget : {512, 4096}) {
    ig::lod::Level0Options o;
    o.triangle_budget = budget;
    o.whole_triangle_error = true;
    const auto whole = ig::lod::build_level0_mesh(hf, o);
    const double worst = worst_sample_error(hf, whole);
    EXPECT_LE(worst, whole.max_error_m + 1e-3) << budget;
    EXPECT_GT(worst, 0.5 * whole.max_error_m) << budget;  // the bound is tight, not a loose overestimate
    o.whole_triangle_error = false;
    const auto nested = ig::lod::build_level0_mesh(hf, o);
    std::printf("budget %d: whole-triangle max error %.1f m (samples %.1f m); nested %.1f m (samples %.1f m)\n", budget,
                whole.max_error_m, worst, nested.max_error_m, worst_sample_error(hf, nested));
    // Spending the same budget on the measured error leaves samples no farther from the mesh.
    EXPECT_LE(worst, worst_sample_error(hf, nested) + 1e-3) << budget;
  }
}

}  // namespace
