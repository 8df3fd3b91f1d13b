#include "lod/roam_wedgie_grid.h"

#include <algorithm>

#include "lod/roam_surface.h"

namespace ig::lod {

RoamWedgieGrid compute_roam_wedgies(const terrain::Heightfield& hf, const PatchGrid& grid) {
  const PaddedHeights H(hf);
  RoamWedgieGrid g;
  const int sx = grid.padded_x(), sy = grid.padded_y();
  g.side_x = sx + 1;
  g.side_y = sy + 1;
  g.error.assign(std::size_t(g.side_x) * g.side_y, 0.0f);
  auto E = [&](int i, int j) -> float& { return g.error[std::size_t(j) * g.side_x + i]; };
  // Finest children (unit triangles) of the axis diamond at (i, j): halves of
  // the four cells around it.
  auto finest = [&](int i, int j) {
    float m = 0.0f;
    for (int cy = std::max(j - 1, 0); cy <= std::min(j, sy - 1); ++cy)
      for (int cx = std::max(i - 1, 0); cx <= std::min(i, sx - 1); ++cx) m = std::max(m, H.diagonal_mismatch(cx, cy));
    return m;
  };

  for (int h = 1; h <= grid.patch / 2; h *= 2) {
    const int h2 = 2 * h, q = h / 2;
    for (int j = 0; j <= sy; j += h2)  // horizontal axis diamonds
      for (int i = h; i < sx; i += h2) {
        float child;
        if (q == 0) {
          child = finest(i, j);
        } else {
          child = 0.0f;
          if (j - q >= 0) child = std::max({child, E(i - q, j - q), E(i + q, j - q)});
          if (j + q <= sy) child = std::max({child, E(i - q, j + q), E(i + q, j + q)});
        }
        E(i, j) = H.deviation(H(i, j), H(i - h, j), H(i + h, j)) + child;
      }
    for (int j = h; j < sy; j += h2)  // vertical axis diamonds
      for (int i = 0; i <= sx; i += h2) {
        float child;
        if (q == 0) {
          child = finest(i, j);
        } else {
          child = 0.0f;
          if (i - q >= 0) child = std::max({child, E(i - q, j - q), E(i - q, j + q)});
          if (i + q <= sx) child = std::max({child, E(i + q, j - q), E(i + q, j + q)});
        }
        E(i, j) = H.deviation(H(i, j), H(i, j - h), H(i, j + h)) + child;
      }
    for (int j = h; j < sy; j += h2)  // square diamonds; children: the axis diamonds on their edges
      for (int i = h; i < sx; i += h2) {
        const bool main = h2 == grid.patch || (((i - h) / h2 + (j - h) / h2) & 1) == 0;
        const float local = main ? H.deviation(H(i, j), H(i - h, j - h), H(i + h, j + h))
                                 : H.deviation(H(i, j), H(i - h, j + h), H(i + h, j - h));
        E(i, j) = local + std::max({E(i - h, j), E(i + h, j), E(i, j - h), E(i, j + h)});
      }
  }
  return g;
}

}  // namespace ig::lod
