#include "lod/drawn_surface_occlusion.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lod/level1_selection.h"

namespace ig::lod {

namespace {

TerrainFloors empty_floors(const terrain::Heightfield& hf, int cell_samples) {
  TerrainFloors f;
  f.cell_samples = cell_samples;
  f.grid_cells_x = std::max(hf.width - 1, 1);
  f.grid_cells_y = std::max(hf.height - 1, 1);
  f.nx = (f.grid_cells_x + cell_samples - 1) / cell_samples;
  f.ny = (f.grid_cells_y + cell_samples - 1) / cell_samples;
  f.floor_m.assign(size_t(f.nx) * f.ny, -std::numeric_limits<float>::infinity());
  return f;
}

constexpr float kNoFloor = -std::numeric_limits<float>::infinity();

}  // namespace

DrawnSurfaceOcclusion::DrawnSurfaceOcclusion(const terrain::Heightfield& hf, const terrain::HeightPyramid& pyramid,
                                             int cell_samples)
    : hf_(hf),
      pyramid_(pyramid),
      cell_samples_(std::max(cell_samples, 1)),
      culling_(empty_floors(hf, std::max(cell_samples, 1)), glm::dvec2(hf.spacing_x_m, hf.spacing_y_m)) {}

int DrawnSurfaceOcclusion::mark_hidden(const glm::dvec3& eye, double earth_radius_m, double min_distance_m,
                                       const std::vector<HorizonCulling::Box>& boxes,
                                       std::vector<std::uint8_t>& hidden, double surface_at_eye_m) {
  hidden.assign(boxes.size(), 0);
  if (!(eye.z > surface_at_eye_m)) return 0;  // the eye must be above what is drawn under it

  TerrainFloors& f = culling_.floors();
  std::fill(f.floor_m.begin(), f.floor_m.end(), std::numeric_limits<float>::infinity());
  const double cell_x = cell_samples_ * hf_.spacing_x_m, cell_y = cell_samples_ * hf_.spacing_y_m;
  auto cell_range = [](double lo, double hi, double cell, int n) {
    return std::pair<int, int>(std::clamp(int(std::floor(lo / cell)), 0, n - 1),
                               std::clamp(int(std::floor(hi / cell)), 0, n - 1));
  };
  for (const auto& b : boxes) {
    if (b.hi.x < 0.0 || b.hi.y < 0.0) continue;
    const auto [i0, i1] = cell_range(b.lo.x, b.hi.x, cell_x, f.nx);
    const auto [j0, j1] = cell_range(b.lo.y, b.hi.y, cell_y, f.ny);
    const float bottom = float(b.lo.z);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        float& floor = f.floor_m[size_t(j) * f.nx + i];
        floor = std::min(floor, bottom);
      }
  }
  for (float& floor : f.floor_m)
    if (floor == std::numeric_limits<float>::infinity()) floor = kNoFloor;  // nothing drawn over it
  return culling_.mark_hidden(eye, earth_radius_m, min_distance_m, boxes, hidden);
}

double DrawnSurfaceOcclusion::dem_max_near(const glm::dvec3& eye, int radius_samples) const {
  const int ci = int(std::floor(eye.x / hf_.spacing_x_m)), cj = int(std::floor(eye.y / hf_.spacing_y_m));
  const int i0 = std::max(ci - radius_samples, 0), i1 = std::min(ci + 1 + radius_samples, hf_.width - 1);
  const int j0 = std::max(cj - radius_samples, 0), j1 = std::min(cj + 1 + radius_samples, hf_.height - 1);
  if (i0 > i1 || j0 > j1) return -std::numeric_limits<double>::infinity();  // off the DEM
  return rect_minmax(pyramid_, i0, j0, i1, j1).hi;
}

int DrawnSurfaceOcclusion::cull_triangles(const glm::dvec3& eye, double earth_radius_m, double min_distance_m,
                                          std::vector<glm::u16vec2>& vertices) {
  const TerrainFloors& f = culling_.floors();
  group_of_cell_.assign(size_t(f.nx) * f.ny, -1);
  groups_.clear();
  const size_t triangles = vertices.size() / 3;
  group_of_triangle_.resize(triangles);
  const double sx = hf_.spacing_x_m, sy = hf_.spacing_y_m;
  const glm::dvec2 eye_sample(eye.x / sx, eye.y / sy);
  double surface_at_eye = -std::numeric_limits<double>::infinity();
  for (size_t t = 0; t < triangles; ++t) {
    const glm::u16vec2* v = &vertices[3 * t];
    const glm::u16vec2 lo = glm::min(v[0], glm::min(v[1], v[2])), hi = glm::max(v[0], glm::max(v[1], v[2]));
    if (eye_sample.x >= lo.x && eye_sample.x <= hi.x && eye_sample.y >= lo.y && eye_sample.y <= hi.y)
      for (int k = 0; k < 3; ++k) surface_at_eye = std::max(surface_at_eye, double(hf_.at(v[k].x, v[k].y)));
    const int ci = std::min((int(v[0].x) + v[1].x + v[2].x) / (3 * cell_samples_), f.nx - 1);
    const int cj = std::min((int(v[0].y) + v[1].y + v[2].y) / (3 * cell_samples_), f.ny - 1);
    std::int32_t& g = group_of_cell_[size_t(cj) * f.nx + ci];
    if (g < 0) {
      g = std::int32_t(groups_.size());
      groups_.push_back({glm::dvec3(std::numeric_limits<double>::infinity()),
                         glm::dvec3(-std::numeric_limits<double>::infinity())});
    }
    group_of_triangle_[t] = g;
    HorizonCulling::Box& box = groups_[size_t(g)];
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 p(v[k].x * sx, v[k].y * sy, hf_.at(v[k].x, v[k].y));
      box.lo = glm::min(box.lo, p);
      box.hi = glm::max(box.hi, p);
    }
  }
  const int count = mark_hidden(eye, earth_radius_m, min_distance_m, groups_, hidden_, surface_at_eye);
  if (count == 0) return 0;
  size_t kept = 0;
  for (size_t t = 0; t < triangles; ++t) {
    if (hidden_[size_t(group_of_triangle_[t])]) continue;
    for (int k = 0; k < 3; ++k) vertices[3 * kept + k] = vertices[3 * t + k];
    ++kept;
  }
  vertices.resize(3 * kept);
  return count;
}

}  // namespace ig::lod
