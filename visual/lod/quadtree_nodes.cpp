#include "lod/quadtree_nodes.h"

#include <algorithm>

#include "lod/roam_surface.h"

namespace ig::lod {
namespace {

struct Deviations {
  float s, n, w, e;  // edge midpoints
  float main, anti;  // centre against the (x0,y0)-(x1,y1) and (x1,y0)-(x0,y1) diagonals
  float edges() const { return std::max({s, n, w, e}); }
  float all() const { return std::max({s, n, w, e, main, anti}); }
};

Deviations deviations(const PaddedHeights& H, int ci, int cj, int h) {
  const float sw = H(ci - h, cj - h), se = H(ci + h, cj - h), nw = H(ci - h, cj + h), ne = H(ci + h, cj + h);
  const float c = H(ci, cj);
  return {H.deviation(H(ci, cj - h), sw, se), H.deviation(H(ci, cj + h), nw, ne),
          H.deviation(H(ci - h, cj), sw, nw), H.deviation(H(ci + h, cj), se, ne),
          H.deviation(c, sw, ne),            H.deviation(c, se, nw)};
}

}  // namespace

QuadtreeNodes compute_quadtree_nodes(const terrain::Heightfield& hf) {
  QuadtreeNodes q;
  q.grid = make_patch_grid(hf.width, hf.height, 2);
  const PaddedHeights H(hf);
  for (int p = q.grid.patch; p > 1; p /= 2) ++q.levels;
  std::size_t total = 0;
  for (int k = 0; k < q.levels; ++k) {
    const int side = 2 << k;
    q.nx.push_back(q.grid.padded_x() / side);
    q.ny.push_back(q.grid.padded_y() / side);
    q.offset.push_back(total);
    total += std::size_t(q.nx.back()) * q.ny.back();
  }
  q.roughness.assign(total, 0.0f);
  q.fan_error.assign(total, 0.0f);
  q.lo.assign(total, 0.0f);
  q.hi.assign(total, 0.0f);

  for (int k = 0; k < q.levels; ++k) {
    const int h = 1 << k, g = h / 2;
    for (int b = 0; b < q.ny[k]; ++b)
      for (int a = 0; a < q.nx[k]; ++a) {
        const int ci = (2 * a + 1) * h, cj = (2 * b + 1) * h;
        const std::size_t n = q.index(k, a, b);
        const Deviations own = deviations(H, ci, cj, h);
        if (k == 0) {
          float lo = H(ci, cj), hi = lo;
          for (int j = cj - 1; j <= cj + 1; ++j)
            for (int i = ci - 1; i <= ci + 1; ++i) {
              lo = std::min(lo, H(i, j));
              hi = std::max(hi, H(i, j));
            }
          q.lo[n] = lo;
          q.hi[n] = hi;
          q.roughness[n] = own.all();
          // The fan splits cells NE and SW along the reference's diagonal, NW and SE across it.
          q.fan_error[n] = std::max(H.diagonal_mismatch(ci - 1, cj), H.diagonal_mismatch(ci, cj - 1));
          continue;
        }
        float lo = 1e30f, hi = -1e30f, child_error = 0.0f, local = 0.0f, rough = own.all();
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) {
            const std::size_t c = q.index(k - 1, 2 * a + dx, 2 * b + dy);
            lo = std::min(lo, q.lo[c]);
            hi = std::max(hi, q.hi[c]);
            child_error = std::max(child_error, q.fan_error[c]);
            rough = std::max(rough, q.roughness[c]);
            // The child's new vertices against this node's fan: its edge
            // midpoints lie on this fan's edges, its centre on this fan's
            // diagonal through the child (main for SW / NE, anti for SE / NW).
            const Deviations d = deviations(H, ci + (2 * dx - 1) * g, cj + (2 * dy - 1) * g, g);
            local = std::max({local, d.edges(), dx == dy ? d.main : d.anti});
          }
        // The 8 half-size nodes just outside the edges (level k-1 indices
        // 2a-1 .. 2a+2 by 2b-1 .. 2b+2 without the corners and the children).
        const int i0 = 2 * a - 1, j0 = 2 * b - 1;
        for (int j = j0; j <= j0 + 3; ++j)
          for (int i = i0; i <= i0 + 3; ++i) {
            const bool corner = (i == i0 || i == i0 + 3) && (j == j0 || j == j0 + 3);
            const bool child = i > i0 && i < i0 + 3 && j > j0 && j < j0 + 3;
            if (corner || child || i < 0 || j < 0 || i >= q.nx[k - 1] || j >= q.ny[k - 1]) continue;
            rough = std::max(rough, q.roughness[q.index(k - 1, i, j)]);
          }
        q.lo[n] = lo;
        q.hi[n] = hi;
        q.fan_error[n] = child_error + local;
        q.roughness[n] = rough;
      }
  }
  return q;
}

}  // namespace ig::lod
