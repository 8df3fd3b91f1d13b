#pragma once
// Occlusion culling by the terrain's own horizon (our addition to the
// two-level method, docs/twolevel.md). Seen from an eye above a heightfield,
// a point is hidden when the straight line to it passes under the drawn
// surface anywhere: the line must then cross the surface in front of it.
// Under each cell of a coarse grid everything below the cell's floor
// (lod/terrain_floors.h) is solid. Per frame the cells are swept from the
// eye outwards, keeping for each direction (azimuth bin) the slope a line
// must exceed to pass over every floor swept so far; a box whose every point
// lies under that slope in every direction it spans, and beyond every floor
// swept, is hidden. Conservative: a box with a point that could be visible
// is never hidden (horizon_culling_test checks against ray casts). Valid only
// while the eye is above the drawn surface (terrain::back_faces_hidden).
//
// Why: at a wide field of view a low eye sees a whole-DEM static Level0 mostly
// from behind ridges; every hidden triangle still costs vertex and set-up
// work on any GPU. No GL here.

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "lod/terrain_floors.h"

namespace ig::lod {

class HorizonCulling {
 public:
  // spacing_m: metres per DEM sample in x and y; bins: azimuth resolution.
  HorizonCulling(TerrainFloors floors, glm::dvec2 spacing_m, int bins = 2048);

  // Boxes in terrain-local metres, heights as in the DEM (before the Earth
  // curvature's drop, which is applied here as the renderer does).
  struct Box {
    glm::dvec3 lo, hi;
  };
  // hidden[k] = 1 where boxes[k] is hidden from `eye` (terrain-local
  // metres) by the floors; boxes nearer than min_distance_m horizontally
  // (the near plane's neighbourhood) are never hidden. Returns how many are.
  int mark_hidden(const glm::dvec3& eye, double earth_radius_m, double min_distance_m, const std::vector<Box>& boxes,
                  std::vector<std::uint8_t>& hidden);
  // The floors in use, for occluders that change per frame (lod/drawn_surface_occlusion.h).
  TerrainFloors& floors() { return floors_; }

 private:
  // A rectangle's horizontal distances from the eye and its directions as
  // bins, unwrapped (they may start below 0 or end past the last bin: the
  // span wraps): the bins its directions touch, and those wholly inside them.
  struct Extent {
    double near, far;
    long touch_lo, touch_hi, inside_lo, inside_hi;
  };
  Extent extent_of(const glm::dvec2& eye, const glm::dvec2& lo, const glm::dvec2& hi) const;
  // The same from the rectangle's sides relative to the eye (x: dx0 < dx1,
  // y: dy0 < dy1) and its corners' pseudo-angles, (x0, y0), (x1, y0),
  // (x0, y1), (x1, y1): neighbouring cells share corners.
  Extent extent_from_corners(double dx0, double dx1, double dy0, double dy1, const std::array<double, 4>& angle) const;
  void raise(const Extent& e, double slope);           // bins wholly inside e's directions
  bool under(const Extent& e, double slope) const;     // every bin e's directions touch
  // Some bin of k0..k1 (unwrapped) has a reach beyond `far`.
  bool reaches_beyond(long k0, long k1, double far) const;

  TerrainFloors floors_;
  glm::dvec2 spacing_;
  std::vector<double> horizon_;  // per bin: a line under this slope passes under some floor swept
  std::vector<double> reach_;    // per bin: the nearest distance of the farthest box spanning it
  static constexpr int kCoarse = 32;
  std::vector<double> coarse_reach_;  // per run of kCoarse bins: the farthest reach in it
  struct Order {
    double distance;
    std::uint32_t index;
    bool operator<(const Order& o) const { return distance < o.distance; }
  };
  std::vector<Order> cells_, box_order_, sorted_;  // per-frame scratch
  std::vector<std::uint32_t> ring_start_;
  template <class RingOf>
  void bucket_by_ring(std::vector<Order>& items, RingOf ring_of);
  std::vector<Extent> cell_extent_, box_extent_;  // the cells kept for the sweep, in the order found; per box
  std::vector<double> cell_floor_;                 // the kept cells' floors
};

// A selection's optional occlusion step: given the boxes in view, marks the
// hidden ones (a HorizonCulling::mark_hidden bound to the frame's eye).
using MarkHidden = std::function<void(const std::vector<HorizonCulling::Box>&, std::vector<std::uint8_t>&)>;

}  // namespace ig::lod
