#include "lod/look_at_point.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>
#include <optional>

#include "terrain/earth_curvature.h"
#include "terrain/ray_cast.h"

namespace ig::lod {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool finite3(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The curvature drop at horizontal distance s, linear between knots every
// kCurvatureKnotM from the eye (the ray cast below walks chords between them).
double knotted_drop(double s, double earth_radius_m) {
  if (!(earth_radius_m > 0.0)) return 0.0;
  const double s0 = std::floor(s / kCurvatureKnotM) * kCurvatureKnotM;
  const double d0 = terrain::curvature_drop(s0, earth_radius_m);
  const double d1 = terrain::curvature_drop(s0 + kCurvatureKnotM, earth_radius_m);
  return d0 + (d1 - d0) * (s - s0) / kCurvatureKnotM;
}

// Horizontal distances [s0, s1] along the half-line eye + s * h (s >= 0, h a
// unit 2D direction) that lie on the DEM's footprint; false when none do.
bool clip_to_footprint(const terrain::Heightfield& hf, glm::dvec2 eye, glm::dvec2 h, double& s0, double& s1) {
  s0 = 0.0;
  s1 = kInf;
  const double extent[2] = {hf.extent_x_m(), hf.extent_y_m()};
  for (int a = 0; a < 2; ++a) {
    if (std::abs(h[a]) < 1e-15) {
      if (eye[a] < 0.0 || eye[a] > extent[a]) return false;
      continue;
    }
    double t0 = (0.0 - eye[a]) / h[a], t1 = (extent[a] - eye[a]) / h[a];
    if (t0 > t1) std::swap(t0, t1);
    s0 = std::max(s0, t0);
    s1 = std::min(s1, t1);
  }
  return s0 <= s1;
}

// The first hit of the centre ray on the drawn surface. Flat: one exact cast.
// Curved: the drawn surface is h - drop(d); equivalently the ray, lifted by
// the (knotted) drop, meets the flat DEM. Cast chord by chord between knots.
std::optional<glm::dvec3> cast_centre_ray(const terrain::Heightfield& hf, const terrain::HeightPyramid& pyramid,
                                          const glm::dvec3& eye, const glm::dvec3& dir, double earth_radius_m) {
  const double hlen = glm::length(glm::dvec2(dir));
  if (!(earth_radius_m > 0.0) || hlen < 1e-9) {  // a vertical ray has no horizontal distance: no drop
    const auto hit = terrain::cast_ray(hf, pyramid, eye, dir);
    if (!hit) return std::nullopt;
    return hit->point;
  }
  const glm::dvec2 h = glm::dvec2(dir) / hlen;
  double s0, s1;
  if (!clip_to_footprint(hf, glm::dvec2(eye), h, s0, s1)) return std::nullopt;
  auto at = [&](double s) {  // the lifted ray at horizontal distance s
    glm::dvec3 p = eye + dir * (s / hlen);
    p.z += knotted_drop(s, earth_radius_m);
    return p;
  };
  for (double s = s0; s < s1;) {
    const double next = std::min(s1, (std::floor(s / kCurvatureKnotM) + 1.0) * kCurvatureKnotM);
    const glm::dvec3 a = at(s), b = at(next);
    if (const auto hit = terrain::cast_ray(hf, pyramid, a, b - a, glm::length(b - a))) return hit->point;
    // Above every height and rising (the lifted ray only steepens): nothing further.
    if (a.z > hf.max_m && b.z > a.z) break;
    s = next;
  }
  return std::nullopt;
}

// Along the drawn profile under the half-line eye + s * h, the elevation
// slope (H(s) - z) / s of each point seen from the eye. In that vertical
// plane a ray of slope m meets the profile exactly when min <= m <= max, and
// at either end of that range it touches it at the argmin / argmax. The
// profile is linear between cell edges, cell diagonals and curvature knots,
// and (H(s) - z) / s is monotonic on each linear piece, so both extremes lie
// at one of those breakpoints.
struct ProfileExtremes {
  double max_slope = -kInf, max_s = 0.0;
  double min_slope = kInf, min_s = 0.0;
};

std::optional<ProfileExtremes> profile_extremes(const terrain::Heightfield& hf, const glm::dvec3& eye, glm::dvec2 h,
                                                double earth_radius_m, double& s0, double& s1) {
  if (!clip_to_footprint(hf, glm::dvec2(eye), h, s0, s1)) return std::nullopt;
  ProfileExtremes x;
  x.max_s = x.min_s = s0;
  auto consider = [&](double s) {
    if (!(s >= s0 && s <= s1)) return;
    const double px = eye.x + h.x * s, py = eye.y + h.y * s;
    const double height = hf.sample_surface(px, py) - knotted_drop(s, earth_radius_m) - eye.z;
    const double slope = s > 0.0 ? height / s : (height > 0.0 ? kInf : -kInf);
    if (slope > x.max_slope || (slope == x.max_slope && s < x.max_s)) {
      x.max_slope = slope;
      x.max_s = s;
    }
    if (slope < x.min_slope || (slope == x.min_slope && s < x.min_s)) {
      x.min_slope = slope;
      x.min_s = s;
    }
  };
  // Crossings of the linear function g(s) = g0 + gs * s with whole numbers.
  auto crossings = [&](double g0, double gs) {
    if (std::abs(gs) < 1e-15) return;
    const double a = g0 + gs * s0, b = g0 + gs * s1;
    for (double k = std::ceil(std::min(a, b)); k <= std::floor(std::max(a, b)); k += 1.0) consider((k - g0) / gs);
  };
  consider(s0);
  consider(s1);
  const double sx = hf.spacing_x_m, sy = hf.spacing_y_m;
  crossings(eye.x / sx, h.x / sx);                                  // cell edges x = i * sx
  crossings(eye.y / sy, h.y / sy);                                  // cell edges y = j * sy
  crossings(eye.x / sx - eye.y / sy, h.x / sx - h.y / sy);          // diagonals (i,j)-(i+1,j+1)
  if (earth_radius_m > 0.0) crossings(0.0, 1.0 / kCurvatureKnotM);  // knots
  return x;
}

// Where a missing ray of slope m passes closest to the profile: above it
// all (m > max), the point it clears least; below it all (m < min, e.g.
// passing under the DEM's near edge, or from under the terrain), the point
// it misses least. Either is where the ray touches the terrain at the switch.
std::optional<glm::dvec3> fallback_on_profile(const terrain::Heightfield& hf, const glm::dvec3& eye, glm::dvec2 h,
                                              double slope, double earth_radius_m) {
  double s0, s1;
  const auto x = profile_extremes(hf, eye, h, earth_radius_m, s0, s1);
  if (!x) return std::nullopt;
  const bool above = slope > x->max_slope ||
                     (!(slope < x->min_slope) && std::abs(slope - x->max_slope) <= std::abs(slope - x->min_slope));
  const double s = above ? x->max_s : x->min_s;
  const double px = std::clamp(eye.x + h.x * s, 0.0, hf.extent_x_m());
  const double py = std::clamp(eye.y + h.y * s, 0.0, hf.extent_y_m());
  return glm::dvec3(px, py, hf.sample_surface(px, py));
}

// The DEM point nearest the half-line eye + s * h (which misses the DEM): a
// corner of the footprint, or its point nearest the eye.
glm::dvec3 nearest_to_line(const terrain::Heightfield& hf, const glm::dvec3& eye, glm::dvec2 h) {
  const double X = hf.extent_x_m(), Y = hf.extent_y_m();
  const glm::dvec2 e(eye);
  const glm::dvec2 candidates[5] = {{std::clamp(e.x, 0.0, X), std::clamp(e.y, 0.0, Y)}, {0, 0}, {X, 0}, {0, Y}, {X, Y}};
  glm::dvec2 best = candidates[0];
  double best_d = kInf;
  for (const auto& c : candidates) {
    const double t = std::max(0.0, glm::dot(c - e, h));
    const double d = glm::length(c - (e + h * t));
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  return {best.x, best.y, hf.sample_surface(best.x, best.y)};
}

}  // namespace

LookAtPoint find_look_at_point(const terrain::Heightfield& hf, const terrain::HeightPyramid& pyramid,
                               const glm::dvec3& eye, const glm::dvec3& dir_in, const glm::dvec3& hint,
                               double earth_radius_m) {
  LookAtPoint e;
  const double cx = 0.5 * hf.extent_x_m(), cy = 0.5 * hf.extent_y_m();
  if (!finite3(eye) || !finite3(dir_in) || glm::length(dir_in) < 1e-12) {  // no view: the DEM's centre
    e.point = {cx, cy, hf.sample_surface(cx, cy)};
    return e;
  }
  const glm::dvec3 dir = glm::normalize(dir_in);
  if (const auto hit = cast_centre_ray(hf, pyramid, eye, dir, earth_radius_m)) {
    e.point = *hit;
    e.hit = true;
    return e;
  }
  // The view's horizontal direction; when vertical, the direction it tends
  // to when pitching about the body's right axis (see the header).
  glm::dvec2 h(dir.x, dir.y);
  if (glm::length(h) > 1e-9) {
    h = glm::normalize(h);
  } else {
    h = glm::dvec2(hint) * (dir.z > 0.0 ? -1.0 : 1.0);
    h = glm::length(h) > 1e-9 && std::isfinite(h.x) && std::isfinite(h.y) ? glm::normalize(h) : glm::dvec2(0.0, 1.0);
  }
  const double hlen = glm::length(glm::dvec2(dir));
  const double slope = hlen > 1e-9 ? dir.z / hlen : (dir.z > 0.0 ? kInf : -kInf);
  if (const auto p = fallback_on_profile(hf, eye, h, slope, earth_radius_m))
    e.point = *p;
  else
    e.point = nearest_to_line(hf, eye, h);
  return e;
}

}  // namespace ig::lod
