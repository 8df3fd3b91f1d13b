#pragma once
// What the view-dependent LODs' error measures (ROAM wedgies, quadtree fan
// errors) need to know about the surface: heights over the padded patch
// grid (outside the DEM: the nearest edge sample) and how far their
// full-resolution triangulation departs from the reference's.
//
// The reference (render/grid_mesh) splits every cell along its (i,j)-(i+1,j+1)
// diagonal. A bintree at full resolution, and a quadtree's 3 x 3 fans, split
// cell (cx, cy) along that diagonal when cx + cy is even and along the other
// one when it is odd; the two triangulations of one cell differ by at most
// |h00 + h11 - h10 - h01| / 2 (at its centre). Counting that keeps the
// methods' error bounds honest against the reference image.

#include <algorithm>
#include <cmath>

#include "terrain/heightfield.h"

namespace ig::lod {

class PaddedHeights {
 public:
  explicit PaddedHeights(const terrain::Heightfield& hf) : hf_(hf), w_(hf.width), h_(hf.height) {
    float m = 0.0f;
    for (float v : hf.heights) m = std::max(m, std::fabs(v));
    // Below this a deviation is float round-off: a tilted plane must come out flat.
    eps_ = std::max(m, 1.0f) * std::ldexp(1.0f, -20);
  }
  float operator()(int i, int j) const {
    return hf_.heights[std::size_t(std::clamp(j, 0, h_ - 1)) * w_ + std::clamp(i, 0, w_ - 1)];
  }
  // |a - (b + c) / 2|, flushed to 0 below round-off.
  float deviation(float a, float b, float c) const {
    const float d = std::fabs(a - 0.5f * (b + c));
    return d <= eps_ ? 0.0f : d;
  }
  // Largest height difference between the LODs' split of cell (cx, cy) and the reference's.
  float diagonal_mismatch(int cx, int cy) const { return ((cx + cy) & 1) == 0 ? 0.0f : twist(cx, cy); }
  // Difference between the two ways of splitting cell (cx, cy).
  float twist(int cx, int cy) const {
    const float d = 0.5f * std::fabs((*this)(cx, cy) + (*this)(cx + 1, cy + 1) - (*this)(cx + 1, cy) -
                                     (*this)(cx, cy + 1));
    return d <= eps_ ? 0.0f : d;
  }

 private:
  const terrain::Heightfield& hf_;
  int w_, h_;
  float eps_ = 0.0f;
};

}  // namespace ig::lod
