#pragma once
// A heightfield read row by row, south to north, whether its heights are
// held whole or paged (a paged DEM is read through its tile cache a strip of
// tiles at a time, so a pass over it holds one strip, not the DEM). The water
// passes (detection, levels, the shore field) read through it, so a paged
// DEM gives them exactly the samples a whole load does. No GL.

#include <vector>

#include "terrain/heightfield.h"

namespace ig::water {

class HeightRows {
 public:
  explicit HeightRows(const terrain::Heightfield& hf);
  int width() const { return hf_.width; }
  int height() const { return hf_.height; }
  // Row j (0 <= j < height()), width() heights. For a paged heightfield the
  // pointer stays valid until a row outside the current strip is asked for.
  const float* row(int j);

 private:
  const terrain::Heightfield& hf_;
  std::vector<float> strip_;
  int strip_first_ = 0, strip_rows_ = 0;
};

}  // namespace ig::water
