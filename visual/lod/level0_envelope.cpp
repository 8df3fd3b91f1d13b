#include "lod/level0_envelope.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace ig::lod {

Level0Envelope level0_upper_envelope(const Level0Mesh& mesh, const terrain::Heightfield& hf, double earth_radius_m) {
  Level0Envelope env;
  env.lift_m.assign(mesh.samples.size(), 0.0f);
  const auto& idx = mesh.indices;
  for (size_t t = 0; t + 2 < idx.size(); t += 3) {
    const glm::ivec2 a = mesh.samples[idx[t]], b = mesh.samples[idx[t + 1]], c = mesh.samples[idx[t + 2]];
    const double ha = hf.at(a.x, a.y), hb = hf.at(b.x, b.y), hc = hf.at(c.x, c.y);
    // Barycentric coordinates over the integer sample grid.
    const double den = double(b.y - c.y) * (a.x - c.x) + double(c.x - b.x) * (a.y - c.y);
    if (den == 0.0) continue;
    const glm::ivec2 lo = glm::max(glm::min(a, glm::min(b, c)), glm::ivec2(0));
    const glm::ivec2 hi = glm::min(glm::max(a, glm::max(b, c)), glm::ivec2(hf.width - 1, hf.height - 1));
    double cut = 0.0;
    for (int j = lo.y; j <= hi.y; ++j)
      for (int i = lo.x; i <= hi.x; ++i) {
        const double wa = (double(b.y - c.y) * (i - c.x) + double(c.x - b.x) * (j - c.y)) / den;
        const double wb = (double(c.y - a.y) * (i - c.x) + double(a.x - c.x) * (j - c.y)) / den;
        const double wc = 1.0 - wa - wb;
        if (wa < -1e-9 || wb < -1e-9 || wc < -1e-9) continue;  // outside (edges count for both sides)
        cut = std::max(cut, double(hf.at(i, j)) - (wa * ha + wb * hb + wc * hc));
      }
    if (earth_radius_m > 0.0) {
      const glm::dvec2 s(hf.spacing_x_m, hf.spacing_y_m);
      const double l = std::max({glm::length(glm::dvec2(a - b) * s), glm::length(glm::dvec2(b - c) * s),
                                 glm::length(glm::dvec2(c - a) * s)});
      cut += l * l / (8.0 * earth_radius_m);
    }
    env.max_cut_m = std::max(env.max_cut_m, cut);
    for (int k = 0; k < 3; ++k) {
      float& lift = env.lift_m[idx[t + k]];
      lift = std::max(lift, cut > 0.0 ? float(cut + 0.01) : 0.0f);  // round up past float rounding
    }
  }
  for (float l : env.lift_m) env.max_lift_m = std::max(env.max_lift_m, double(l));
  return env;
}

}  // namespace ig::lod
