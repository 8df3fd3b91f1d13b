#include "terrain/terrain_query.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "terrain/earth_curvature.h"
#include "terrain/ray_cast.h"

namespace ig::terrain {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A line of sight is followed in at most this many chords (a 1 cm sag with
// R = 6371 km gives 714 m chords: 7000 chords cover 5000 km).
constexpr int kMaxChords = 7000;

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

// Parameter t (metres along unit d from o) where the horizontal line leaves
// the footprint [0, ex] x [0, ey]; -inf when it never is inside it.
double footprint_exit(const glm::dvec3& o, const glm::dvec3& d, double ex, double ey) {
  double enter = 0.0, exit = kInf;
  const double lo[2] = {0.0, 0.0}, hi[2] = {ex, ey};
  for (int a = 0; a < 2; ++a) {
    if (d[a] == 0.0) {
      if (o[a] < lo[a] || o[a] > hi[a]) return -kInf;
      continue;
    }
    double t0 = (lo[a] - o[a]) / d[a], t1 = (hi[a] - o[a]) / d[a];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    exit = std::min(exit, t1);
  }
  return enter <= exit ? exit : -kInf;
}

}  // namespace

TerrainQuery::TerrainQuery(const Heightfield& hf, double earth_radius_m)
    : hf_(hf), pyramid_(hf), earth_radius_m_(earth_radius_m > 0.0 ? earth_radius_m : 0.0) {}

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
  return surface_in_cell(hf_, i, j, fx, fy);
}

void TerrainQuery::prefetch(double x_m, double y_m) const {
  if (!inside(x_m, y_m)) return;
  const int i = std::clamp(int(x_m / hf_.spacing_x_m), 0, hf_.width - 2);
  const int j = std::clamp(int(y_m / hf_.spacing_y_m), 0, hf_.height - 2);
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
    if (s && std::abs(s->height_m - from.z) <= 1e-9) return LosHit{0.0, from, s->normal};
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
  const double horizontal = std::hypot(d.x, d.y);
  const double R = earth_radius_m_;

  // Where the line (in the flat frame) is at range t: bent up by the drop.
  auto at = [&](double t) {
    glm::dvec3 p = from + t * d;
    p.z += curvature_drop(t * horizontal, R);
    return p;
  };
  double t_end = max_range_m;
  if (horizontal > 0.0) {  // nothing past the footprint's far side
    const double exit = footprint_exit(from, d, hf_.extent_x_m(), hf_.extent_y_m());
    if (exit == -kInf) return std::nullopt;
    t_end = std::min(t_end, exit + 1e-9 * (1.0 + exit));
  }
  if (t_end < min_range_m) return std::nullopt;

  int chords = 1;
  if (R > 0.0 && horizontal > 0.0) {
    // Sag of a chord of horizontal length L under a parabola of curvature
    // 1/R: L^2 / 8R.
    const double chord_h = std::sqrt(8.0 * R * std::max(chord_tolerance_m_, 1e-6));
    const double span_h = (t_end - min_range_m) * horizontal;
    chords = int(std::clamp(std::ceil(span_h / chord_h), 1.0, double(kMaxChords)));
  }
  auto answer = [&](const RayHit& hit, double range) {
    const double fx = std::clamp(hit.point.x / hf_.spacing_x_m - hit.cell_i, 0.0, 1.0);
    const double fy = std::clamp(hit.point.y / hf_.spacing_y_m - hit.cell_j, 0.0, 1.0);
    return LosHit{range, hit.point, surface_in_cell(hf_, hit.cell_i, hit.cell_j, fx, fy).normal};
  };
  if (!std::isfinite(t_end)) {  // vertical, unbounded: one straight cast
    const auto hit = cast_ray(hf_, pyramid_, at(min_range_m), d, kInf);
    if (!hit) return std::nullopt;
    return answer(*hit, min_range_m + hit->t);
  }
  const double top = pyramid_.root().hi;
  const double step = (t_end - min_range_m) / chords;
  for (int k = 0; k < chords; ++k) {
    const double t0 = min_range_m + step * k, t1 = k + 1 == chords ? t_end : t0 + step;
    const glm::dvec3 a = at(t0), b = at(t1);
    // The path's height is convex in t: once above every sample and rising
    // (d.z >= 0), it stays above.
    if (a.z > top && d.z >= 0.0) break;
    const double chord_len = glm::length(b - a);
    std::optional<RayHit> hit;
    if (chord_len > 0.0) {
      hit = cast_ray(hf_, pyramid_, a, b - a, chord_len);
    } else if (const auto s = surface_at(a.x, a.y); s && std::abs(s->height_m - a.z) <= 1e-9) {
      hit = RayHit{0.0, a, s->cell_i, s->cell_j};
    }
    if (!hit) continue;
    // Range is proportional along a chord (both ends lie on the line).
    const double frac = chord_len > 0.0 ? hit->t / chord_len : 0.0;
    return answer(*hit, t0 + frac * (t1 - t0));
  }
  return std::nullopt;
}

}  // namespace ig::terrain
