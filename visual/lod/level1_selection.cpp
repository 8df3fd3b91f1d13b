#include "lod/level1_selection.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace ig::lod {

Level1Placement guard_level1_for_eye(Level1Placement p, glm::dvec2 eye_grid, double eye_agl_m,
                                     double level0_max_error_m, const std::vector<int>& ladder,
                                     glm::ivec2 dem_size) {
  p.eye_guarded = false;
  const double ei = eye_grid.x, ej = eye_grid.y;
  if (ladder.empty() || ei < 0 || ej < 0 || ei > dem_size.x - 1 || ej > dem_size.y - 1) return p;  // not over the DEM
  if (!(eye_agl_m < kEyeGuardHeightFactor * std::max(level0_max_error_m, 1.0))) return p;
  const double di = std::fabs(ei - p.centre.x), dj = std::fabs(ej - p.centre.y);
  const int needed = 2 * int(std::ceil(std::max(di, dj))) + 2 * kEyeGuardMarginSamples + 1;
  int guarded = ladder.back();
  for (int size : ladder)
    if (size >= needed) {
      guarded = size;
      break;
    }
  p.eye_guarded = guarded > p.n || needed > ladder.back();
  p.n = std::max(p.n, guarded);
  if (needed > p.n) {  // too far for the largest square: start it behind the eye, towards E
    const double half = 0.5 * (p.n - 1) - kEyeGuardMarginSamples;
    const double d = std::max(di, dj);
    p.centre = {int(std::lround(ei + (p.centre.x - ei) * half / d)), int(std::lround(ej + (p.centre.y - ej) * half / d))};
  }
  return p;
}

int band_width_samples(double level0_resolution, double alpha, int n, int stride) {
  stride = std::max(1, stride);
  const double w = level0_resolution * alpha * (n - 1);
  return std::clamp(int(std::lround(w / stride)) * stride, stride, std::max(stride, (n - 1) / 4 / stride * stride));
}

terrain::HeightPyramid::MinMax rect_minmax(const terrain::HeightPyramid& p, int i0, int j0, int i1, int j1) {
  i0 = std::clamp(i0, 0, p.cells_x() - 1);
  j0 = std::clamp(j0, 0, p.cells_y() - 1);
  i1 = std::clamp(i1, i0 + 1, p.cells_x());
  j1 = std::clamp(j1, j0 + 1, p.cells_y());
  int level = 0;
  while (level + 1 < p.num_levels() && (1 << (level + 1)) <= std::max(i1 - i0, j1 - j0)) ++level;
  terrain::HeightPyramid::MinMax m{1e30f, -1e30f};
  for (int j = j0 >> level; j <= (j1 - 1) >> level; ++j)
    for (int i = i0 >> level; i <= (i1 - 1) >> level; ++i) {
      const auto node = p.node(level, i, j);
      m.lo = std::min(m.lo, node.lo);
      m.hi = std::max(m.hi, node.hi);
    }
  return m;
}

std::vector<glm::ivec2> visible_level1_blocks(const terrain::Heightfield& hf, const terrain::HeightPyramid& p,
                                              glm::ivec2 origin, int n, double below_m, const BoxVisible& visible,
                                              glm::dvec2 eye_grid, const MarkHidden& mark_hidden) {
  constexpr int q = kLevel1BlockQuads;
  std::vector<glm::ivec2> out;
  std::vector<HorizonCulling::Box> boxes;
  const int blocks = (n - 1 + q - 1) / q;
  for (int bj = 0; bj < blocks; ++bj)
    for (int bi = 0; bi < blocks; ++bi) {
      const glm::ivec2 o = origin + glm::ivec2(bi, bj) * q;
      const auto mm = rect_minmax(p, o.x, o.y, o.x + q, o.y + q);
      const glm::dvec3 lo(o.x * hf.spacing_x_m, o.y * hf.spacing_y_m, mm.lo - below_m);
      const glm::dvec3 hi((o.x + q) * hf.spacing_x_m, (o.y + q) * hf.spacing_y_m, mm.hi);
      if (!visible(lo, hi)) continue;
      out.push_back(o);
      boxes.push_back({lo, hi});
    }
  if (mark_hidden) {
    std::vector<std::uint8_t> hidden;
    mark_hidden(boxes, hidden);
    size_t kept = 0;
    for (size_t k = 0; k < out.size(); ++k)
      if (!hidden[k]) out[kept++] = out[k];
    out.resize(kept);
  }
  std::sort(out.begin(), out.end(), [&](glm::ivec2 a, glm::ivec2 b) {
    const glm::dvec2 ca = glm::dvec2(a) + 0.5 * q - eye_grid, cb = glm::dvec2(b) + 0.5 * q - eye_grid;
    return glm::dot(ca, ca) < glm::dot(cb, cb);
  });
  return out;
}

}  // namespace ig::lod
