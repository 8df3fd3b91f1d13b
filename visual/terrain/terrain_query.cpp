#include "terrain/terrain_query.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "terrain/earth_curvature.h"
#include "terrain/ray_cast.h"
#include "water/shore_field.h"
#include "water/water_map.h"

namespace ig::terrain {
namespace {

bool finite3(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The triangle of cell (i, j) under fractional position (fx, fy) in the cell:
// lower (i,j),(i+1,j),(i+1,j+1) when fx >= fy, else upper (i,j),(i+1,j+1),(i,j+1).
SurfacePoint surface_in_cell(const Heightfield& hf, int i, int j, double fx, double fy) {
  const double h00 = hf.at(i, j), h10 = hf.at(i + 1, j), h01 = hf.at(i, j + 1), h11 = hf.at(i + 1, j + 1);
  double h, dhdx, dhdy;
  if (fx >= fy) {
    h = h00 + (h10 - h00) * fx + (h11 - h10) * fy;
    dhdx = (h10 - h00) / hf.spacing_x_m;
    dhdy = (h11 - h10) / hf.spacing_y_m;
  } else {
    h = h00 + (h01 - h00) * fy + (h11 - h01) * fx;
    dhdx = (h11 - h01) / hf.spacing_x_m;
    dhdy = (h01 - h00) / hf.spacing_y_m;
  }
  return SurfacePoint{h, glm::normalize(glm::dvec3(-dhdx, -dhdy, 1.0)), i, j};
}

}  // namespace

TerrainQuery::TerrainQuery(const Heightfield& hf, double earth_radius_m)
    : hf_(hf),
      owned_pyramid_(std::make_unique<HeightPyramid>(hf)),
      pyramid_(*owned_pyramid_),
      earth_radius_m_(earth_radius_m > 0.0 ? earth_radius_m : 0.0) {}

TerrainQuery::TerrainQuery(const Heightfield& hf, const HeightPyramid& pyramid, double earth_radius_m)
    : hf_(hf), pyramid_(pyramid), earth_radius_m_(earth_radius_m > 0.0 ? earth_radius_m : 0.0) {
  if (pyramid.cells_x() != std::max(hf.width - 1, 0) || pyramid.cells_y() != std::max(hf.height - 1, 0))
    throw std::invalid_argument("TerrainQuery: the pyramid was not built from this heightfield");
}

bool TerrainQuery::inside(double x_m, double y_m) const {
  return hf_.width >= 2 && hf_.height >= 2 && x_m >= 0.0 && y_m >= 0.0 && x_m <= hf_.extent_x_m() &&
         y_m <= hf_.extent_y_m();
}

std::optional<SurfacePoint> TerrainQuery::surface_at(double x_m, double y_m) const {
  if (!inside(x_m, y_m)) return std::nullopt;  // NaN fails the comparisons too
  const double gx = x_m / hf_.spacing_x_m, gy = y_m / hf_.spacing_y_m;
  const int i = std::clamp(int(gx), 0, hf_.width - 2), j = std::clamp(int(gy), 0, hf_.height - 2);
  // Clamped to the cell so rounding at the far edges stays in it.
  const double fx = std::clamp(gx - i, 0.0, 1.0), fy = std::clamp(gy - j, 0.0, 1.0);
  SurfacePoint s = surface_in_cell(hf_, i, j, fx, fy);
  if (hf_.water) {
    const auto shore = water::shore_at(*hf_.water, gx, gy);
    if (shore && shore->water() && shore->body) {
      s.height_m = hf_.water->bodies()[*shore->body].level_m;
      s.normal = glm::dvec3(0.0, 0.0, 1.0);
      s.material = SurfaceMaterial::Water;
    }
  }
  return s;
}

void TerrainQuery::prefetch(double x_m, double y_m) const {
  if (!inside(x_m, y_m)) return;
  const int i = std::clamp(int(x_m / hf_.spacing_x_m), 0, hf_.width - 2);
  const int j = std::clamp(int(y_m / hf_.spacing_y_m), 0, hf_.height - 2);
  if (hf_.paged) return;  // read through the tile cache
  const float* row = hf_.heights.data() + std::size_t(j) * std::size_t(hf_.width) + std::size_t(i);
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(row);
  __builtin_prefetch(row + hf_.width);
#endif
}

std::optional<LosHit> TerrainQuery::segment(const glm::dvec3& from, const glm::dvec3& to) const {
  if (!finite3(from) || !finite3(to)) return std::nullopt;
  // The target as seen in the source's tangent frame (lowered by the drop).
  const double d = std::hypot(to.x - from.x, to.y - from.y);
  const glm::dvec3 dir = glm::dvec3(to.x, to.y, to.z - curvature_drop(d, earth_radius_m_)) - from;
  const double len = glm::length(dir);
  if (len == 0.0) {
    const auto s = surface_at(from.x, from.y);
    if (s && std::abs(s->height_m - from.z) <= 1e-9) return LosHit{0.0, from, s->normal, s->material};
    return std::nullopt;
  }
  return ray(from, dir, 0.0, len);
}

std::optional<LosHit> TerrainQuery::ray(const glm::dvec3& from, const glm::dvec3& dir_in, double min_range_m,
                                        double max_range_m) const {
  if (!finite3(from) || !finite3(dir_in) || !std::isfinite(min_range_m) || std::isnan(max_range_m) ||
      min_range_m < 0.0 || min_range_m > max_range_m || pyramid_.empty())
    return std::nullopt;
  const double len = glm::length(dir_in);
  if (!(len > 0.0) || !std::isfinite(len)) return std::nullopt;
  const glm::dvec3 d = dir_in / len;
  // Straight in the source's tangent frame, against the samples lowered by
  // their drop from the source (what the renderer draws for an eye there).
  const Curvature curve{from.x, from.y, earth_radius_m_};
  const auto hit = cast_ray(hf_, pyramid_, from + min_range_m * d, d, max_range_m - min_range_m, curve);
  std::optional<LosHit> out;
  if (hit) {
    // Back to the flat DEM frame: the same (x, y), on the DEM's own triangle.
    const double fx = std::clamp(hit->point.x / hf_.spacing_x_m - hit->cell_i, 0.0, 1.0);
    const double fy = std::clamp(hit->point.y / hf_.spacing_y_m - hit->cell_j, 0.0, 1.0);
    const SurfacePoint s = surface_in_cell(hf_, hit->cell_i, hit->cell_j, fx, fy);
    out = LosHit{min_range_m + hit->t, glm::dvec3(hit->point.x, hit->point.y, s.height_m), s.normal};
    // Terrain the picture draws water on (the shore's edge) is water too.
    if (hf_.water) {
      const auto shore = water::shore_at(*hf_.water, hit->point.x / hf_.spacing_x_m, hit->point.y / hf_.spacing_y_m);
      if (shore && shore->water()) out->material = SurfaceMaterial::Water;
    }
  }
  if (hf_.water) {
    const auto wet = water_hit(from, d, min_range_m, out ? out->range_m : max_range_m);
    if (wet && (!out || wet->range_m < out->range_m)) out = wet;
  }
  return out;
}

std::optional<LosHit> TerrainQuery::water_hit(const glm::dvec3& from, const glm::dvec3& d, double min_range_m,
                                              double max_range_m) const {
  // Along the line z(t) = from.z + t d.z, a level L lowered by the drop over
  // the horizontal distance t h (h = |d.xy|): from.z + t d.z = L - (t h)^2 / 2R.
  const double h2 = d.x * d.x + d.y * d.y;
  const double a = earth_radius_m_ > 0.0 ? h2 / (2.0 * earth_radius_m_) : 0.0;
  std::optional<LosHit> best;
  for (std::size_t k = 0; k < hf_.water->bodies().size(); ++k) {
    const water::WaterBody& b = hf_.water->bodies()[k];
    const double c = from.z - b.level_m;
    double t = -1.0;
    if (a > 0.0) {
      const double disc = d.z * d.z - 4.0 * a * c;
      if (disc < 0.0) continue;
      const double r = std::sqrt(disc);
      // The smaller root at or past min_range first.
      for (const double root : {(-d.z - r) / (2.0 * a), (-d.z + r) / (2.0 * a)})
        if (root >= min_range_m) {
          t = root;
          break;
        }
    } else if (d.z != 0.0) {
      t = -c / d.z;
    } else if (c == 0.0) {
      t = min_range_m;  // along the surface itself
    }
    if (!(t >= min_range_m && t <= max_range_m) || (best && t >= best->range_m)) continue;
    const glm::dvec3 p = from + t * d;
    // Inside the body's box (and the shore's reach), and water there.
    const double si = p.x / hf_.spacing_x_m, sj = p.y / hf_.spacing_y_m, reach = water::kShoreRadius + 1;
    if (si < b.min_i - reach || si > b.max_i + reach || sj < b.min_j - reach || sj > b.max_j + reach) continue;
    const auto shore = water::shore_at(*hf_.water, si, sj);
    if (!shore || !shore->water() || shore->body != std::optional<std::uint32_t>(std::uint32_t(k))) continue;
    best = LosHit{t, glm::dvec3(p.x, p.y, b.level_m), glm::dvec3(0.0, 0.0, 1.0), SurfaceMaterial::Water};
  }
  return best;
}

}  // namespace ig::terrain
