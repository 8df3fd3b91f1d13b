#include "lod/roam_tessellator.h"

#include "lod/bintree_split.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace ig::lod {

RoamTessellator::RoamTessellator(const terrain::Heightfield& hf, double earth_radius_m)
    : hf_(hf), grid_(make_patch_grid(hf.width, hf.height)), heights_(hf),
      earth_radius_m_(earth_radius_m > 0.0 && std::isfinite(earth_radius_m) ? earth_radius_m : 0.0) {
  if (hf.heights.size() != std::size_t(hf.width) * std::size_t(hf.height))
    throw std::invalid_argument("roam: heightfield has " + std::to_string(hf.heights.size()) +
                                " heights for " + std::to_string(hf.width) + " x " + std::to_string(hf.height));
  if (!(hf.spacing_x_m > 0.0) || !(hf.spacing_y_m > 0.0) || !std::isfinite(hf.spacing_x_m * hf.spacing_y_m))
    throw std::invalid_argument("roam: sample spacing must be positive and finite");
  if (grid_.padded_x() > 65535 || grid_.padded_y() > 65535)
    throw std::invalid_argument("roam: DEMs wider or taller than 64513 samples are not supported");
  const auto t0 = std::chrono::steady_clock::now();
  wedgies_ = compute_roam_wedgies(hf, grid_);
  build_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

float RoamTessellator::error_of(const Tri& t) const {
  const glm::ivec2 l(t.v[1]), r(t.v[2]);
  const glm::ivec2 s = l + r;
  if ((s.x & 1) == 0 && (s.y & 1) == 0) return wedgies_.at(s.x / 2, s.y / 2);
  // A unit triangle: its hypotenuse is a cell diagonal; off the reference's
  // diagonal it differs from the reference by the cell's twist.
  const glm::ivec2 d = r - l;
  if (d.x * d.y > 0) return 0.0f;
  const glm::ivec2 cell = glm::min(l, r);
  return heights_.twist(cell.x, cell.y);
}

void RoamTessellator::evaluate(Tri& t) const {
  const glm::ivec2 a(t.v[0]), b(t.v[1]), c(t.v[2]);
  const glm::ivec2 mn = glm::min(a, glm::min(b, c)), mx = glm::max(a, glm::max(b, c));
  const bool crossing = grid_.crosses_edge(mx.x, mx.y);
  double e = double(error_of(t)) * (crossing ? 2.0 : 1.0);
  if (earth_radius_m_ > 0.0) {
    const glm::dvec2 h = glm::dvec2(glm::ivec2(t.v[1]) - glm::ivec2(t.v[2])) * glm::dvec2(hf_.spacing_x_m, hf_.spacing_y_m);
    e += (h.x * h.x + h.y * h.y) / (8.0 * earth_radius_m_);
  }
  const float h0 = heights_(a.x, a.y), h1 = heights_(b.x, b.y), h2 = heights_(c.x, c.y);
  const glm::dvec3 lo(mn.x * hf_.spacing_x_m, mn.y * hf_.spacing_y_m, std::min({h0, h1, h2}) - e);
  const glm::dvec3 hi(std::min(mx.x, grid_.lim_x) * hf_.spacing_x_m, std::min(mx.y, grid_.lim_y) * hf_.spacing_y_m,
                      std::max({h0, h1, h2}) + e);
  if (*in_view_ && !(*in_view_)(lo - eye_, hi - eye_)) {
    t.ratio = kCulled;
    return;
  }
  const glm::dvec3 d = glm::max(glm::max(lo - eye_, eye_ - hi), glm::dvec3(0.0));
  const double dist = std::max(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z), min_distance_);
  t.ratio = float(e / dist);
}

void RoamTessellator::split(int x, bool forced) {
  bintree::split(
      tris_, x, forced,
      [this](bool f) {
        ++sel_.stats.splits;
        if (f) ++sel_.stats.forced_splits;
      },
      [](int, int) {}, [](int, int) {});
}

void RoamTessellator::refine(int id) {
  if (tris_[id].child >= 0) {  // split by a neighbour's forced split already
    const int c = tris_[id].child;
    refine(c);
    refine(c + 1);
    return;
  }
  Tri& t = tris_[id];
  const glm::ivec2 a(t.v[0]), b(t.v[1]), c(t.v[2]);
  const glm::ivec2 mn = glm::min(a, glm::min(b, c));
  if (!grid_.overlaps_dem(mn.x, mn.y)) return;
  const glm::ivec2 s = b + c;
  if ((s.x & 1) || (s.y & 1)) return;  // unit triangle: full resolution
  evaluate(t);
  if (!(double(t.ratio) > threshold_)) return;  // also when culled (negative)
  split(id, false);
  const int first = tris_[id].child;
  refine(first);
  refine(first + 1);
}

void RoamTessellator::emit(int id) {
  Tri& t = tris_[id];
  const glm::ivec2 a(t.v[0]), b(t.v[1]), c(t.v[2]);
  const glm::ivec2 mn = glm::min(a, glm::min(b, c)), mx = glm::max(a, glm::max(b, c));
  if (!grid_.overlaps_dem(mn.x, mn.y)) return;
  if (t.ratio == kUnknown) evaluate(t);
  if (t.ratio == kCulled) {
    ++sel_.stats.culled;
    return;
  }
  sel_.stats.max_error_ratio = std::max(sel_.stats.max_error_ratio, double(t.ratio));
  if (!grid_.crosses_edge(mx.x, mx.y)) {
    sel_.vertices.push_back(t.v[0]);
    sel_.vertices.push_back(t.v[1]);
    sel_.vertices.push_back(t.v[2]);
    ++sel_.stats.triangles;
    return;
  }
  glm::ivec2 clipped[3][3];
  const int n = clip_to_dem(a, b, c, grid_.lim_x, grid_.lim_y, clipped);
  for (int k = 0; k < n; ++k)
    for (const auto& p : clipped[k]) sel_.vertices.emplace_back(p.x, p.y);
  sel_.stats.triangles += n;
}

RoamSelection RoamTessellator::select(const glm::dvec3& eye, double tau_px, double pixels_per_radian,
                                     const BoxInView& in_view, double min_distance_m, RoamSelection recycled) {
  if (!(tau_px >= 0.0) || !std::isfinite(tau_px) || !(pixels_per_radian > 0.0) || !std::isfinite(pixels_per_radian) ||
      !(min_distance_m > 0.0) || !std::isfinite(eye.x + eye.y + eye.z))
    throw std::invalid_argument(
        "roam: tau_px must be finite and >= 0, pixels per radian and the minimum distance > 0, the eye finite");
  eye_ = eye;
  min_distance_ = min_distance_m;
  threshold_ = tau_px / pixels_per_radian;
  in_view_ = &in_view;
  tris_.clear();
  sel_ = std::move(recycled);
  sel_.vertices.clear();
  sel_.stats = {};

  // Roots: per patch (x0,y0)-(x1,y1), root 0 = (SE, NE, SW) (left edge east,
  // right edge south), root 1 = (NW, SW, NE) (left edge west, right edge
  // north); their bases are the shared main diagonal.
  const int P = grid_.patch;
  auto root = [&](int px, int py, int k) { return 2 * (py * grid_.nx + px) + k; };
  for (int py = 0; py < grid_.ny; ++py)
    for (int px = 0; px < grid_.nx; ++px) {
      const int x0 = px * P, y0 = py * P, x1 = x0 + P, y1 = y0 + P;
      Tri a, b;
      a.v[0] = glm::u16vec2(x1, y0), a.v[1] = glm::u16vec2(x1, y1), a.v[2] = glm::u16vec2(x0, y0);
      b.v[0] = glm::u16vec2(x0, y1), b.v[1] = glm::u16vec2(x0, y0), b.v[2] = glm::u16vec2(x1, y1);
      a.base = root(px, py, 1);
      b.base = root(px, py, 0);
      a.left = px + 1 < grid_.nx ? root(px + 1, py, 1) : -1;
      a.right = py > 0 ? root(px, py - 1, 1) : -1;
      b.left = px > 0 ? root(px - 1, py, 0) : -1;
      b.right = py + 1 < grid_.ny ? root(px, py + 1, 0) : -1;
      tris_.push_back(a);
      tris_.push_back(b);
    }
  const int roots = int(tris_.size());
  for (int r = 0; r < roots; ++r) refine(r);
  // The leaves, in the order they were made: a linear pass over the pool.
  for (int id = 0; id < int(tris_.size()); ++id)
    if (tris_[id].child < 0) emit(id);
  sel_.stats.nodes = (long long)tris_.size();
  in_view_ = nullptr;
  return std::move(sel_);
}

}  // namespace ig::lod
