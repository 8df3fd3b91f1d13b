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
  // spacing_m: metres per DEM sample in x and y. Far from the eye the floors
  // are swept in coarser cells (each the lowest of the 2 x 2 below it): a
  // cell is swept whole where its width spans at most bins_per_whole_cell
  // bins, so a larger value sweeps fewer cells and hides a little less.
  // bins: azimuth resolution.
  HorizonCulling(TerrainFloors floors, glm::dvec2 spacing_m, double bins_per_whole_cell = 32.0, int bins = 2048);

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
  TerrainFloors& floors() {
    floor_levels_valid_ = false;
    return floors_;
  }
  const TerrainFloors& floors() const { return floors_; }

 private:
  // A rectangle's horizontal distances from the eye and its directions as
  // bins, unwrapped (they may start below 0 or end past the last bin: the
  // span wraps): the bins its directions touch, and those wholly inside them.
  struct Extent {
    double near, far;
    long touch_lo, touch_hi, inside_lo, inside_hi;
  };
  Extent extent_of(const glm::dvec2& eye, const glm::dvec2& lo, const glm::dvec2& hi) const;
  void raise(const Extent& e, double slope);           // bins wholly inside e's directions
  bool under(const Extent& e, double slope) const;     // every bin e's directions touch
  // Some bin of k0..k1 (unwrapped) has a reach beyond `far`.
  bool reaches_beyond(long k0, long k1, double far) const;
  // Fills cells_, cell_extent_ and cell_floor_ for this frame's sweep.
  void gather_cells(const glm::dvec2& eye2, double earth_radius_m, double min_distance_m, double farthest_box);

  TerrainFloors floors_;
  // Coarser floors, each cell the lowest of the 2 x 2 below it: far from the
  // eye a cell of the finest grid spans few bins, and one coarse cell raises
  // them at a quarter of the cost. floor_levels_[0] is floors_'s grid (its
  // floors are floors_'s); rebuilt after floors() was handed out for writing.
  struct Level {
    int nx, ny, cell_samples;
    std::vector<float> floor_m, chord_samples;  // as TerrainFloors's
  };
  std::vector<Level> floor_levels_;
  bool floor_levels_valid_ = false;
  void build_floor_levels();
  const std::vector<float>& level_floors(size_t level) const;  // floors_'s at level 0
  const std::vector<float>& level_chords(size_t level) const;
  glm::dvec2 spacing_;
  double bins_per_whole_cell_;
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
  struct Node {
    int level, i, j;  // a cell of floor_levels_[level]
  };
  std::vector<Node> node_stack_;
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
