#include "lod/chunk_grid_error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ig::lod {
namespace {

int clamp_i(const terrain::Heightfield& hf, int i) { return std::clamp(i, 0, hf.width - 1); }
int clamp_j(const terrain::Heightfield& hf, int j) { return std::clamp(j, 0, hf.height - 1); }

}  // namespace

HeightRange sample_height_range(const terrain::Heightfield& hf, int i0, int j0, int n_i, int n_j) {
  const int ia = clamp_i(hf, i0), ib = clamp_i(hf, i0 + n_i);
  const int ja = clamp_j(hf, j0), jb = clamp_j(hf, j0 + n_j);
  HeightRange r{hf.at(ia, ja), hf.at(ia, ja)};
  for (int j = ja; j <= jb; ++j)
    for (int i = ia; i <= ib; ++i) {
      const float h = hf.at(i, j);
      r.min_m = std::min(r.min_m, h);
      r.max_m = std::max(r.max_m, h);
    }
  return r;
}

float grid_max_error(const terrain::Heightfield& hf, int i0, int j0, int quads, int stride) {
  if (stride <= 1) return 0.0f;  // every sample is a vertex
  double worst = 0.0;
  for (int qj = 0; qj < quads; ++qj) {
    const int y0 = clamp_j(hf, j0 + qj * stride), y1 = clamp_j(hf, j0 + (qj + 1) * stride);
    if (y1 == y0) continue;  // folded onto the edge: the quad below covers these samples
    for (int qi = 0; qi < quads; ++qi) {
      const int x0 = clamp_i(hf, i0 + qi * stride), x1 = clamp_i(hf, i0 + (qi + 1) * stride);
      if (x1 == x0) continue;
      const double h00 = hf.at(x0, y0), h10 = hf.at(x1, y0), h01 = hf.at(x0, y1), h11 = hf.at(x1, y1);
      const double sx = 1.0 / (x1 - x0), sy = 1.0 / (y1 - y0);
      for (int y = y0; y <= y1; ++y) {
        const double v = (y - y0) * sy;
        for (int x = x0; x <= x1; ++x) {
          const double u = (x - x0) * sx;
          // Same split as the mesh: (x0,y0)-(x1,y1) diagonal.
          const double m = u >= v ? h00 + u * (h10 - h00) + v * (h11 - h10) : h00 + v * (h01 - h00) + u * (h11 - h01);
          worst = std::max(worst, std::abs(m - double(hf.at(x, y))));
        }
      }
    }
  }
  return float(worst);
}

int grid_triangle_count(const terrain::Heightfield& hf, int i0, int j0, int quads, int stride) {
  int nx = 0, ny = 0;
  for (int q = 0; q < quads; ++q) {
    nx += clamp_i(hf, i0 + (q + 1) * stride) > clamp_i(hf, i0 + q * stride);
    ny += clamp_j(hf, j0 + (q + 1) * stride) > clamp_j(hf, j0 + q * stride);
  }
  return 2 * nx * ny;
}

namespace {

struct ClampedTriangle {
  glm::ivec2 a, b, c;
  std::int64_t area2;  // twice the signed area
};

ClampedTriangle clamp_triangle(const terrain::Heightfield& hf, int i0, int j0, const glm::ivec2* t) {
  auto cl = [&](glm::ivec2 p) { return glm::ivec2(clamp_i(hf, i0 + p.x), clamp_j(hf, j0 + p.y)); };
  ClampedTriangle r{cl(t[0]), cl(t[1]), cl(t[2]), 0};
  r.area2 = std::int64_t(r.b.x - r.a.x) * (r.c.y - r.a.y) - std::int64_t(r.b.y - r.a.y) * (r.c.x - r.a.x);
  return r;
}

}  // namespace

float triangles_max_error(const terrain::Heightfield& hf, int i0, int j0, const std::vector<glm::ivec2>& corners) {
  double worst = 0.0;
  for (size_t k = 0; k + 2 < corners.size(); k += 3) {
    const ClampedTriangle t = clamp_triangle(hf, i0, j0, &corners[k]);
    if (t.area2 == 0) continue;
    const double ha = hf.at(t.a.x, t.a.y), hb = hf.at(t.b.x, t.b.y), hc = hf.at(t.c.x, t.c.y);
    const int xlo = std::min({t.a.x, t.b.x, t.c.x}), xhi = std::max({t.a.x, t.b.x, t.c.x});
    const int ylo = std::min({t.a.y, t.b.y, t.c.y}), yhi = std::max({t.a.y, t.b.y, t.c.y});
    const double inv = 1.0 / double(t.area2);
    for (int y = ylo; y <= yhi; ++y)
      for (int x = xlo; x <= xhi; ++x) {
        // Edge functions in exact integers; the sign of the area orients them.
        const std::int64_t wa = std::int64_t(t.b.x - x) * (t.c.y - y) - std::int64_t(t.b.y - y) * (t.c.x - x);
        const std::int64_t wb = std::int64_t(t.c.x - x) * (t.a.y - y) - std::int64_t(t.c.y - y) * (t.a.x - x);
        const std::int64_t wc = t.area2 - wa - wb;
        const bool inside = t.area2 > 0 ? (wa >= 0 && wb >= 0 && wc >= 0) : (wa <= 0 && wb <= 0 && wc <= 0);
        if (!inside) continue;
        const double m = (double(wa) * ha + double(wb) * hb + double(wc) * hc) * inv;
        worst = std::max(worst, std::abs(m - double(hf.at(x, y))));
      }
  }
  return float(worst);
}

int triangles_nondegenerate_count(const terrain::Heightfield& hf, int i0, int j0,
                                  const std::vector<glm::ivec2>& corners) {
  int n = 0;
  for (size_t k = 0; k + 2 < corners.size(); k += 3) n += clamp_triangle(hf, i0, j0, &corners[k]).area2 != 0;
  return n;
}

}  // namespace ig::lod
