#include "lod/horizon_culling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "terrain/earth_curvature.h"

namespace ig::lod {

namespace {

// Direction of (dx, dy) as a number in [0, 4) that grows with the angle (a
// quarter turn per unit): cheaper than atan2, and bins need only the order.
double pseudo_angle(double dx, double dy) {
  const double r = dy / (std::abs(dx) + std::abs(dy));
  if (dx >= 0) return dy >= 0 ? r : 4.0 + r;
  return 2.0 - r;
}

// Float rounding of drawn positions and the shaders' curvature: floors are
// taken this much lower and boxes this much higher.
constexpr double kMarginM = 0.1;

constexpr int kRings = 512;

}  // namespace

// Orders `items` by ring_of(distance), stable within a ring.
template <class RingOf>
void HorizonCulling::bucket_by_ring(std::vector<Order>& items, RingOf ring_of) {
  ring_start_.assign(kRings + 2, 0);
  for (const Order& o : items) ++ring_start_[ring_of(o.distance) + 1];
  for (int r = 0; r <= kRings; ++r) ring_start_[r + 1] += ring_start_[r];
  sorted_.resize(items.size());
  for (const Order& o : items) sorted_[ring_start_[ring_of(o.distance)]++] = o;
  items.swap(sorted_);
}

HorizonCulling::HorizonCulling(TerrainFloors floors, glm::dvec2 spacing_m, double bins_per_whole_cell, int bins)
    : floors_(std::move(floors)),
      spacing_(spacing_m),
      bins_per_whole_cell_(bins_per_whole_cell),
      horizon_(size_t(std::max(bins, 4))),
      reach_(horizon_.size()) {}

const std::vector<float>& HorizonCulling::level_floors(size_t level) const {
  return level == 0 ? floors_.floor_m : floor_levels_[level].floor_m;
}

const std::vector<float>& HorizonCulling::level_chords(size_t level) const {
  return level == 0 ? floors_.chord_samples : floor_levels_[level].chord_samples;
}

// Rebuilt in place: the baselines' occluders change every frame, and the
// levels keep their sizes, so no frame allocates.
void HorizonCulling::build_floor_levels() {
  size_t count = 1;
  for (int nx = floors_.nx, ny = floors_.ny; nx > 4 || ny > 4; nx = (nx + 1) / 2, ny = (ny + 1) / 2) ++count;
  floor_levels_.resize(count);
  floor_levels_[0] = {floors_.nx, floors_.ny, floors_.cell_samples, {}, {}};  // its cells are floors_'s
  for (size_t k = 1; k < count; ++k) {
    const Level& f = floor_levels_[k - 1];
    const std::vector<float>& floor = level_floors(k - 1);
    const std::vector<float>& chord = level_chords(k - 1);
    Level& c = floor_levels_[k];
    c.nx = (f.nx + 1) / 2;
    c.ny = (f.ny + 1) / 2;
    c.cell_samples = 2 * f.cell_samples;
    c.floor_m.assign(size_t(c.nx) * c.ny, std::numeric_limits<float>::infinity());
    c.chord_samples.assign(chord.empty() ? 0 : c.floor_m.size(), 0.0f);
    for (int j = 0; j < f.ny; ++j)
      for (int i = 0; i < f.nx; ++i) {
        const size_t to = size_t(j / 2) * c.nx + i / 2, from = size_t(j) * f.nx + i;
        c.floor_m[to] = std::min(c.floor_m[to], floor[from]);
        if (!chord.empty()) c.chord_samples[to] = std::max(c.chord_samples[to], chord[from]);
      }
  }
  floor_levels_valid_ = true;
}

HorizonCulling::Extent HorizonCulling::extent_of(const glm::dvec2& eye, const glm::dvec2& lo,
                                                 const glm::dvec2& hi) const {
  const double dx0 = lo.x - eye.x, dx1 = hi.x - eye.x, dy0 = lo.y - eye.y, dy1 = hi.y - eye.y;
  const std::array<double, 4> angle{pseudo_angle(dx0, dy0), pseudo_angle(dx1, dy0), pseudo_angle(dx0, dy1),
                                    pseudo_angle(dx1, dy1)};
  const double nx = std::max({dx0, 0.0, -dx1}), ny = std::max({dy0, 0.0, -dy1});
  const double fx = std::max(std::abs(dx0), std::abs(dx1));
  const double fy = std::max(std::abs(dy0), std::abs(dy1));
  const double near = std::sqrt(nx * nx + ny * ny), far = std::sqrt(fx * fx + fy * fy);
  double angle_lo = 0.0, angle_hi = 4.0;  // the eye is over it: every direction
  if (near > 0.0) {
    // The eye is outside the rectangle, which therefore spans less than half
    // a turn: the corners' directions relative to the first one bound it.
    const double a0 = angle[0];
    double dlo = 0.0, dhi = 0.0;
    for (int k = 1; k < 4; ++k) {
      double d = angle[size_t(k)] - a0;
      if (d > 2.0) d -= 4.0;
      if (d < -2.0) d += 4.0;
      dlo = std::min(dlo, d);
      dhi = std::max(dhi, d);
    }
    angle_lo = a0 + dlo;
    angle_hi = a0 + dhi;
  }
  const double scale = double(horizon_.size()) / 4.0;
  const double lo_bins = angle_lo * scale, hi_bins = angle_hi * scale;
  return {near, far, long(std::floor(lo_bins)), long(std::floor(hi_bins)), long(std::ceil(lo_bins)),
          long(std::floor(hi_bins)) - 1};
}

namespace {
// Calls f(bin) for bins k0..k1 (unwrapped indices, k0 <= k1 + 1) modulo
// `bins` while f returns true; returns false where f stopped it. Unwrapped
// indices stay within a turn or two of [0, bins): no division needed.
template <class F>
bool each_bin(long k0, long k1, int bins, F f) {
  if (k1 - k0 + 1 >= bins) k1 = k0 + bins - 1;
  long b = k0;
  while (b < 0) b += bins;
  while (b >= bins) b -= bins;
  for (long k = k0; k <= k1; ++k) {
    if (!f(size_t(b))) return false;
    if (++b == bins) b = 0;
  }
  return true;
}
}  // namespace

bool HorizonCulling::reaches_beyond(long k0, long k1, double far) const {
  const int bins = int(horizon_.size());
  if (k1 < k0) return false;
  if (k1 - k0 + 1 >= bins) k1 = k0 + bins - 1;
  long b = k0;
  while (b < 0) b += bins;
  while (b >= bins) b -= bins;
  for (long k = k0; k <= k1;) {
    // A whole run of kCoarse bins at once: any bin in it reaching beyond
    // `far` answers true, none lets the run be skipped.
    if (b % kCoarse == 0 && k + kCoarse - 1 <= k1 && b + kCoarse <= bins) {
      if (coarse_reach_[size_t(b / kCoarse)] > far) return true;
      k += kCoarse;
      b += kCoarse;
    } else {
      if (reach_[size_t(b)] > far) return true;
      ++k;
      ++b;
    }
    if (b >= bins) b -= bins;
  }
  return false;
}

void HorizonCulling::raise(const Extent& e, double slope) {
  each_bin(e.inside_lo, e.inside_hi, int(horizon_.size()), [&](size_t b) {
    horizon_[b] = std::max(horizon_[b], slope);
    return true;
  });
}

bool HorizonCulling::under(const Extent& e, double slope) const {
  return each_bin(e.touch_lo, e.touch_hi, int(horizon_.size()), [&](size_t b) { return slope < horizon_[b]; });
}

// The cells a box's test may use, with their extents and floors as drawn. A
// floor ending at distance `far` can change a box's test only where some box
// spanning one of the bins it raises lies beyond it (reaches_beyond): a
// floor is swept only before boxes beyond its far end.
void HorizonCulling::gather_cells(const glm::dvec2& eye2, double earth_radius_m, double min_distance_m,
                                  double farthest_box) {
  cells_.clear();
  cell_extent_.clear();
  cell_floor_.clear();
  if (!floor_levels_valid_) build_floor_levels();
  // From the coarsest cells down: a cell that cannot matter from its nearest
  // point holds none that can (a cell's directions and distances lie inside
  // its parent's); one that spans few bins is swept whole, with the lowest
  // floor under it; nearer ones are split into their four quarters.
  const double bin_angle = 2.0 * M_PI / double(horizon_.size());
  node_stack_.clear();
  const Level& top = floor_levels_.back();
  for (int j = top.ny - 1; j >= 0; --j)
    for (int i = top.nx - 1; i >= 0; --i) node_stack_.push_back({int(floor_levels_.size()) - 1, i, j});
  while (!node_stack_.empty()) {
    const auto [level, i, j] = node_stack_.back();
    node_stack_.pop_back();
    const Level& l = floor_levels_[size_t(level)];
    const int s = l.cell_samples;
    const double x0 = std::min(i * s, floors_.grid_cells_x) * spacing_.x;
    const double x1 = std::min((i + 1) * s, floors_.grid_cells_x) * spacing_.x;
    const double y0 = std::min(j * s, floors_.grid_cells_y) * spacing_.y;
    const double y1 = std::min((j + 1) * s, floors_.grid_cells_y) * spacing_.y;
    const Extent e = extent_of(eye2, {x0, y0}, {x1, y1});
    if (e.near > farthest_box) continue;
    if (e.near > 0.0 && !reaches_beyond(e.inside_lo, e.inside_hi, e.near)) continue;
    const bool whole = e.near >= min_distance_m && e.far <= farthest_box &&
                       std::max(x1 - x0, y1 - y0) <= bins_per_whole_cell_ * bin_angle * e.near;
    if (level > 0 && !whole) {
      const Level& finer = floor_levels_[size_t(level - 1)];
      for (int dj = 1; dj >= 0; --dj)
        for (int di = 1; di >= 0; --di)
          if (2 * i + di < finer.nx && 2 * j + dj < finer.ny) node_stack_.push_back({level - 1, 2 * i + di, 2 * j + dj});
      continue;
    }
    if (e.near < min_distance_m || e.far > farthest_box) continue;
    if (!reaches_beyond(e.inside_lo, e.inside_hi, e.far)) continue;
    cells_.push_back({e.far, std::uint32_t(cell_extent_.size())});
    cell_extent_.push_back(e);
    const size_t at = size_t(j) * l.nx + i;
    const std::vector<float>& chord = level_chords(size_t(level));
    // The chord sag of the triangles over the cell (terrain_floors.h).
    const double chord_m = chord.empty() ? 0.0 : chord[at] * std::max(spacing_.x, spacing_.y);
    const double sag = earth_radius_m > 0.0 ? chord_m * chord_m / (8.0 * earth_radius_m) : 0.0;
    cell_floor_.push_back(level_floors(size_t(level))[at] - sag);
  }
}

int HorizonCulling::mark_hidden(const glm::dvec3& eye, double earth_radius_m, double min_distance_m,
                                const std::vector<Box>& boxes, std::vector<std::uint8_t>& hidden) {
  hidden.assign(boxes.size(), 0);
  if (floors_.floor_m.empty() || boxes.empty()) return 0;
  const glm::dvec2 eye2(eye.x, eye.y);
  const int bins = int(horizon_.size());

  // The boxes nearest first, and per direction the farthest a floor may
  // end and still be swept before some box there (the nearest distance of
  // the farthest box spanning that bin; -1: no box spans it).
  box_order_.clear();
  box_extent_.resize(boxes.size());
  std::fill(reach_.begin(), reach_.end(), -1.0);
  double farthest_box = 0.0;
  for (size_t k = 0; k < boxes.size(); ++k) {
    const Extent& e = box_extent_[k] = extent_of(eye2, glm::dvec2(boxes[k].lo), glm::dvec2(boxes[k].hi));
    if (e.near < min_distance_m) continue;
    box_order_.push_back({e.near, std::uint32_t(k)});
    farthest_box = std::max(farthest_box, e.near);
    each_bin(e.touch_lo, e.touch_hi, bins, [&](size_t b) {
      reach_[b] = std::max(reach_[b], e.near);
      return true;
    });
  }
  // Per run of kCoarse bins the farthest reach in it, for reaches_beyond().
  coarse_reach_.assign((size_t(bins) + kCoarse - 1) / kCoarse, -1.0);
  for (int b = 0; b < bins; ++b) coarse_reach_[size_t(b / kCoarse)] = std::max(coarse_reach_[size_t(b / kCoarse)], reach_[size_t(b)]);
  // Distances in rings of this width: a floor is swept before a box when
  // its ring is nearer than the box's (a counting sort, not a full sort).
  const double ring = std::max(farthest_box, 1.0) / kRings;
  auto ring_of = [&](double d) { return std::min(int(d / ring), kRings); };
  bucket_by_ring(box_order_, ring_of);
  // Floors in order of their farthest point: a floor is used only for boxes
  // wholly beyond it, so where a line passes under it, that is in front of
  // the box. Floors beyond every box, or in no box's directions, cannot matter.
  gather_cells(eye2, earth_radius_m, min_distance_m, farthest_box);
  bucket_by_ring(cells_, ring_of);

  std::fill(horizon_.begin(), horizon_.end(), -std::numeric_limits<double>::infinity());
  size_t next_cell = 0;
  int count = 0;
  for (const Order& b : box_order_) {
    for (const int box_ring = ring_of(b.distance); next_cell < cells_.size() && ring_of(cells_[next_cell].distance) < box_ring;
         ++next_cell) {
      const auto k = cells_[next_cell].index;
      const Extent& e = cell_extent_[k];
      // The floor as drawn, lowest at the cell's far corner; a line at this
      // slope or lower in any direction inside the cell passes under it.
      const double rise = cell_floor_[k] - kMarginM - terrain::curvature_drop(e.far, earth_radius_m) - eye.z;
      raise(e, rise / (rise < 0.0 ? e.near : e.far));
    }
    const Extent& e = box_extent_[b.index];
    // The box's top as drawn, highest at its nearest point: no point of the
    // box is seen at a steeper slope than this.
    const double rise = boxes[b.index].hi.z + kMarginM - terrain::curvature_drop(e.near, earth_radius_m) - eye.z;
    if (under(e, rise / (rise >= 0.0 ? e.near : e.far))) {
      hidden[b.index] = 1;
      ++count;
    }
  }
  return count;
}

}  // namespace ig::lod
