#include "lod/quadtree_tessellator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <string>

namespace ig::lod {

QuadtreeTessellator::QuadtreeTessellator(const terrain::Heightfield& hf)
    : hf_(hf), heights_(hf), inv_spacing_(1.0 / std::sqrt(hf.spacing_x_m * hf.spacing_y_m)) {
  if (!std::isfinite(inv_spacing_) || !(hf.spacing_x_m > 0.0) || !(hf.spacing_y_m > 0.0))
    throw std::invalid_argument("quadtree: sample spacing must be positive and finite");
  if (hf.width < 2 || hf.height < 2 || hf.heights.size() != std::size_t(hf.width) * std::size_t(hf.height))
    throw std::invalid_argument("quadtree: heightfield must be at least 2 x 2 with width * height heights");
  if (hf.width > 65536 || hf.height > 65536)
    throw std::invalid_argument("quadtree: DEMs wider or taller than 65536 samples are not supported");
  const auto t0 = std::chrono::steady_clock::now();
  nodes_ = compute_quadtree_nodes(hf);
  split_.assign(nodes_.count(), 0);
  build_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

bool QuadtreeTessellator::exists(int k, int a, int b) const {
  if (a < 0 || b < 0 || a >= nodes_.nx[k] || b >= nodes_.ny[k]) return false;
  return k + 1 == nodes_.levels || split_[nodes_.index(k + 1, a / 2, b / 2)] != 0;
}

bool QuadtreeTessellator::inside_dem(int k, int a, int b) const {
  const int side = 2 << k;
  return nodes_.grid.overlaps_dem(a * side, b * side);
}

void QuadtreeTessellator::evaluate(int k, int a, int b) {
  if (k == 0 || !inside_dem(k, a, b)) return;  // size-2 nodes are full resolution
  const std::size_t n = nodes_.index(k, a, b);
  const int h = 1 << k, ci = (2 * a + 1) * h, cj = (2 * b + 1) * h;
  const double sx = hf_.spacing_x_m, sy = hf_.spacing_y_m;
  if (*in_view_) {
    const glm::dvec3 lo((ci - h) * sx, (cj - h) * sy, nodes_.lo[n]);
    const glm::dvec3 hi(std::min(ci + h, nodes_.grid.lim_x) * sx, std::min(cj + h, nodes_.grid.lim_y) * sy,
                        nodes_.hi[n]);
    if (!(*in_view_)(lo - eye_, hi - eye_)) return;
  }
  ++sel_.stats.evaluated;
  const glm::dvec3 centre = glm::dvec3(ci * sx, cj * sy, heights_(ci, cj)) - eye_;
  const double L = std::sqrt(centre.x * centre.x + centre.y * centre.y + centre.z * centre.z);
  const double d = 2.0 * h * std::max(sx, sy);
  // f = L / (d * C1 * max(C2 * DHmax, 1)) < 1, DHmax in sample spacings (as
  // the seed's grid-unit heights), so the criterion does not depend on units.
  if (!(L < d * c1_ * std::max(c2_ * nodes_.roughness[n] * inv_spacing_, 1.0))) return;
  split_[n] = 1;
  split_list_.push_back({k, a, b});
  ++sel_.stats.splits;
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) evaluate(k - 1, 2 * a + dx, 2 * b + dy);
}

void QuadtreeTessellator::force_split(int k, int a, int b) {
  const std::size_t n = nodes_.index(k, a, b);
  if (split_[n]) return;
  if (k + 1 < nodes_.levels) force_split(k + 1, a / 2, b / 2);  // the node must exist first
  split_[n] = 1;
  split_list_.push_back({k, a, b});
  ++sel_.stats.forced_splits;
}

void QuadtreeTessellator::restrict_levels() {
  // Every split node needs its 4 same-size neighbours to exist (else a leaf
  // two or more levels coarser touches its children).
  static constexpr int kDir[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (std::size_t i = 0; i < split_list_.size(); ++i) {
    const NodeRef p = split_list_[i];
    if (p.k + 1 == nodes_.levels) continue;  // roots always exist
    for (const auto& dir : kDir) {
      const int a = p.a + dir[0], b = p.b + dir[1];
      if (a < 0 || b < 0 || a >= nodes_.nx[p.k] || b >= nodes_.ny[p.k] || !inside_dem(p.k, a, b)) continue;
      if (!split_[nodes_.index(p.k + 1, a / 2, b / 2)]) force_split(p.k + 1, a / 2, b / 2);
    }
  }
}

void QuadtreeTessellator::emit(int k, int a, int b) {
  if (!inside_dem(k, a, b)) return;
  if (k > 0 && split_[nodes_.index(k, a, b)]) {
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) emit(k - 1, 2 * a + dx, 2 * b + dy);
    return;
  }
  emit_leaf(k, a, b);
}

void QuadtreeTessellator::emit_leaf(int k, int a, int b) {
  const std::size_t n = nodes_.index(k, a, b);
  const int h = 1 << k, ci = (2 * a + 1) * h, cj = (2 * b + 1) * h;
  const int x0 = ci - h, y0 = cj - h, x1 = ci + h, y1 = cj + h;
  const PatchGrid& g = nodes_.grid;
  const double sx = hf_.spacing_x_m, sy = hf_.spacing_y_m;
  const glm::dvec3 lo(x0 * sx, y0 * sy, nodes_.lo[n]);
  const glm::dvec3 hi(std::min(x1, g.lim_x) * sx, std::min(y1, g.lim_y) * sy, nodes_.hi[n]);
  if (*in_view_ && !(*in_view_)(lo - eye_, hi - eye_)) {
    ++sel_.stats.culled;
    return;
  }
  ++sel_.stats.leaves;

  // Keep an edge midpoint unless the neighbour across that edge is coarser.
  auto keep = [&](int na, int nb) {
    if (na < 0 || nb < 0 || na >= nodes_.nx[k] || nb >= nodes_.ny[k] || !inside_dem(k, na, nb)) return true;
    return exists(k, na, nb);
  };
  const bool keep_s = keep(a, b - 1), keep_e = keep(a + 1, b), keep_n = keep(a, b + 1), keep_w = keep(a - 1, b);
  const glm::ivec2 ring[8] = {{x0, y0}, {ci, y0}, {x1, y0}, {x1, cj}, {x1, y1}, {ci, y1}, {x0, y1}, {x0, cj}};
  const bool kept[8] = {true, keep_s, true, keep_e, true, keep_n, true, keep_w};

  // Error bound. The full fan is within fan_error of the reference; the
  // triangle across a dropped midpoint differs from the full fan by at most
  // that midpoint's deviation, judged over that triangle's own box (so a
  // transition triangle outside the view does not count). Clipped nodes
  // count twice (roam_patch_grid.h).
  const bool crossing = g.crosses_edge(x1, y1);
  const double scale = crossing ? 2.0 : 1.0;
  auto ratio_at = [&](double e, const glm::dvec3& box_lo, const glm::dvec3& box_hi) {
    const glm::dvec3 d = glm::max(glm::max(box_lo - eye_, eye_ - box_hi), glm::dvec3(0.0));
    return e / std::max(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z), min_distance_);
  };
  double fan;  // the full fan's part, the largest over the node
  if (k > 0) {
    fan = ratio_at(nodes_.fan_error[n] * scale, lo, hi);
  } else {
    // Finest nodes, mostly right under the eye: each cell in view split
    // across the reference's diagonal counts at its own distance, much
    // tighter than the node's.
    fan = 0.0;
    for (const glm::ivec2 cell : {glm::ivec2(ci - 1, cj), glm::ivec2(ci, cj - 1)}) {
      if (cell.x >= g.lim_x || cell.y >= g.lim_y) continue;
      const float h00 = heights_(cell.x, cell.y), h10 = heights_(cell.x + 1, cell.y),
                  h01 = heights_(cell.x, cell.y + 1), h11 = heights_(cell.x + 1, cell.y + 1);
      const glm::dvec3 clo(cell.x * sx, cell.y * sy, std::min({h00, h10, h01, h11}));
      const glm::dvec3 chi((cell.x + 1) * sx, (cell.y + 1) * sy, std::max({h00, h10, h01, h11}));
      if (*in_view_ && !(*in_view_)(clo - eye_, chi - eye_)) continue;  // not seen: no image error
      fan = std::max(fan, ratio_at(heights_.diagonal_mismatch(cell.x, cell.y) * scale, clo, chi));
    }
  }
  double ratio = fan;
  for (int m = 1; m < 8; m += 2) {
    if (kept[m]) continue;
    const glm::ivec2 p = ring[m], u = ring[m - 1], v = ring[(m + 1) % 8];
    const double dev = heights_.deviation(heights_(p.x, p.y), heights_(u.x, u.y), heights_(v.x, v.y));
    const glm::ivec2 tmin = glm::min(glm::ivec2(ci, cj), glm::min(u, v)), tmax = glm::max(glm::ivec2(ci, cj), glm::max(u, v));
    const glm::dvec3 tlo(tmin.x * sx, tmin.y * sy, lo.z);
    const glm::dvec3 thi(std::min(tmax.x, g.lim_x) * sx, std::min(tmax.y, g.lim_y) * sy, hi.z);
    if (*in_view_ && !(*in_view_)(tlo - eye_, thi - eye_)) continue;
    ratio = std::max(ratio, fan + ratio_at(dev * scale, tlo, thi));
  }
  sel_.stats.max_error_ratio = std::max(sel_.stats.max_error_ratio, ratio);

  const glm::ivec2 c(ci, cj);
  glm::ivec2 prev = ring[0];
  for (int m = 1; m <= 8; ++m) {
    const int r = m % 8;
    if (!kept[r]) continue;
    const glm::ivec2 next = ring[r];
    if (!crossing) {
      sel_.vertices.emplace_back(c.x, c.y);
      sel_.vertices.emplace_back(prev.x, prev.y);
      sel_.vertices.emplace_back(next.x, next.y);
      ++sel_.stats.triangles;
    } else {
      glm::ivec2 clipped[3][3];
      const int count = clip_to_dem(c, prev, next, g.lim_x, g.lim_y, clipped);
      for (int t = 0; t < count; ++t)
        for (const auto& p : clipped[t]) sel_.vertices.emplace_back(p.x, p.y);
      sel_.stats.triangles += count;
    }
    prev = next;
  }
}

QuadtreeSelection QuadtreeTessellator::select(const glm::dvec3& eye, double c1, double c2, const BoxInView& in_view,
                                              double min_distance_m, QuadtreeSelection recycled) {
  if (!(c1 > 0.0) || !std::isfinite(c1) || !(c2 >= 0.0) || !std::isfinite(c2) || !(min_distance_m > 0.0) ||
      !std::isfinite(eye.x + eye.y + eye.z))
    throw std::invalid_argument(
        "quadtree: C1 must be > 0, C2 >= 0 (both finite), the minimum distance > 0 and the eye finite");
  min_distance_ = min_distance_m;
  for (const NodeRef& r : split_list_) split_[nodes_.index(r.k, r.a, r.b)] = 0;
  split_list_.clear();
  sel_ = std::move(recycled);
  sel_.vertices.clear();
  sel_.stats = {};
  eye_ = eye;
  c1_ = c1;
  c2_ = c2;
  in_view_ = &in_view;
  const int root = nodes_.levels - 1;
  for (int b = 0; b < nodes_.ny[root]; ++b)
    for (int a = 0; a < nodes_.nx[root]; ++a) evaluate(root, a, b);
  restrict_levels();
  for (int b = 0; b < nodes_.ny[root]; ++b)
    for (int a = 0; a < nodes_.nx[root]; ++a) emit(root, a, b);
  in_view_ = nullptr;
  return std::move(sel_);
}

int QuadtreeTessellator::leaf_level(int cx, int cy) const {
  const int P = nodes_.grid.patch;
  if (cx < 0 || cy < 0 || cx >= nodes_.grid.padded_x() || cy >= nodes_.grid.padded_y()) return -1;
  int k = nodes_.levels - 1, a = cx / P, b = cy / P;
  while (k > 0 && split_[nodes_.index(k, a, b)]) {
    const int h = 1 << k;
    a = 2 * a + (cx >= (2 * a + 1) * h ? 1 : 0);
    b = 2 * b + (cy >= (2 * b + 1) * h ? 1 : 0);
    --k;
  }
  return k;
}

}  // namespace ig::lod
