#pragma once
// Which samples a square window over a DEM must fetch when it moves, and
// where they go in a toroidally addressed (wrap-around) store of the same
// size: sample (i, j) always lives at slot (i mod size, j mod size), so a
// move only fetches the rows and columns that scrolled in and never copies
// what stays. Used by the height window texture (render/height_window_texture.h)
// for DEMs larger than one GL texture. No GL here.

#include <vector>

#include <glm/vec2.hpp>

namespace ig::terrain {

// A rectangle of DEM samples [x, x + w) x [y, y + h).
struct SampleRect {
  int x = 0, y = 0, w = 0, h = 0;
  long long samples() const { return static_cast<long long>(w) * h; }
};

class ToroidalWindow {
 public:
  // A size x size window over a dem_w x dem_h grid; size is clamped to the
  // grid (a window as large as the DEM never moves).
  ToroidalWindow(int dem_w, int dem_h, int size);

  int size_x() const { return size_x_; }
  int size_y() const { return size_y_; }
  // South-west sample of the window; meaningful once placed.
  glm::ivec2 origin() const { return origin_; }
  bool placed() const { return placed_; }
  // The window's origin for a window centred on sample `centre`, clamped so
  // the window stays on the DEM.
  glm::ivec2 origin_for(glm::ivec2 centre) const;
  // Moves the window to `origin` (clamped as origin_for does) and returns
  // the sample rectangles now inside it that were not before (all of it
  // the first time, or when it jumps by a whole window or more): at most an
  // L of two rectangles.
  std::vector<SampleRect> move_to(glm::ivec2 origin);
  // Splits a rectangle of samples at the store's wrap-around seams into
  // (at most 4) pieces that are contiguous in the store; each keeps its
  // sample coordinates (its store slot is (x mod size_x, y mod size_y)).
  std::vector<SampleRect> split_at_seams(const SampleRect& r) const;
  glm::ivec2 slot(glm::ivec2 sample) const;

 private:
  int dem_w_, dem_h_, size_x_, size_y_;
  glm::ivec2 origin_{0, 0};
  bool placed_ = false;
};

}  // namespace ig::terrain
