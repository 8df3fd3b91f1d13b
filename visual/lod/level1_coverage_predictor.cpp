#include "lod/level1_coverage_predictor.h"

#include <algorithm>
#include <cmath>

#include "terrain/ray_cast.h"

namespace ig::lod {

glm::ivec2 level1_square_origin(glm::ivec2 e, int n, int dem_width, int dem_height) {
  return {std::clamp(e.x - (n - 1) / 2, 0, std::max(dem_width - n, 0)),
          std::clamp(e.y - (n - 1) / 2, 0, std::max(dem_height - n, 0))};
}

CoveragePrediction predict_level1_coverage(const terrain::Heightfield& hf, const terrain::HeightPyramid& pyramid,
                                           const glm::dvec3& eye, std::span<const glm::dvec3> rays, double max_t,
                                           glm::ivec2 e, const std::vector<int>& ladder) {
  CoveragePrediction p;
  p.rays = int(rays.size());
  std::vector<int> inside(ladder.size(), 0);
  std::vector<glm::ivec2> origins;
  for (int n : ladder) origins.push_back(level1_square_origin(e, n, hf.width, hf.height));
  for (const auto& dir : rays) {
    const auto hit = terrain::cast_ray(hf, pyramid, eye, dir, max_t);
    if (!hit) continue;
    ++p.terrain_hits;
    p.hits.push_back(hit->point);
    const double si = hit->point.x / hf.spacing_x_m, sj = hit->point.y / hf.spacing_y_m;
    for (size_t k = 0; k < ladder.size(); ++k) {
      const glm::ivec2 o = origins[k];
      const double side = ladder[k] - 1;
      if (si >= o.x && si <= o.x + side && sj >= o.y && sj <= o.y + side) ++inside[k];
    }
  }
  if (p.terrain_hits == 0) return p;
  for (int c : inside) p.ratio.push_back(double(c) / p.terrain_hits);
  return p;
}

}  // namespace ig::lod
