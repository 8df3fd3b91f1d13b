#include "gl/grid_mesh.h"

#include <cstdint>
#include <vector>

namespace ig::gl {
namespace {
std::vector<std::int16_t> grid_vertices(int n) {
  std::vector<std::int16_t> verts;
  verts.reserve(size_t(n + 1) * (n + 1) * 2);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      verts.push_back(std::int16_t(i));
      verts.push_back(std::int16_t(j));
    }
  return verts;
}
}  // namespace

GridMesh::GridMesh(int n) : n_(n), mesh_(grid_vertices(n), 2, {{2, 0}}) {
  std::vector<std::uint32_t> idx;
  idx.reserve(size_t(n) * n * 6);
  auto v = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  // Quarter by quarter when n is even (child order: SW, SE, NW, NE), so a
  // quarter is one contiguous index range (CDLOD draws single quarters).
  const int parts = n % 2 == 0 && n > 0 ? 2 : 1, h = n / parts;
  for (int q = 0; q < parts * parts; ++q)
    for (int j = (q / parts) * h; j < (q / parts + 1) * h; ++j)
      for (int i = (q % parts) * h; i < (q % parts + 1) * h; ++i) {
        // (i,j) (i+1,j) (i+1,j+1) and (i,j) (i+1,j+1) (i,j+1): counter-clockwise seen from above.
        idx.insert(idx.end(), {v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j), v(i + 1, j + 1), v(i, j + 1)});
      }
  list_ = mesh_.add_indices(idx);
}

void GridMesh::draw_quadrant(int q) const {
  const int count = index_count() / 4;
  mesh_.draw(list_, q * count, count);
}

}  // namespace ig::gl
