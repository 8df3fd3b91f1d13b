// The overview of a DEM beyond one texture: every step-th sample,
// so each overview sample is the DEM sample at the same place, and the step
// is the smallest that fits the overview in the given side.

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "terrain/heightfield_overview.h"

namespace {

using ig::terrain::Heightfield;

Heightfield ramp(int w, int h) {
  Heightfield hf;
  hf.width = w;
  hf.height = h;
  hf.spacing_x_m = 30.0;
  hf.spacing_y_m = 20.0;
  hf.heights.resize(static_cast<std::size_t>(w) * h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) hf.ref(i, j) = float(i * 1000 + j);
  hf.finalize_stats();
  hf.source = "ramp";
  return hf;
}

TEST(HeightfieldOverview, EachSampleIsTheDemSampleThere) {
  const Heightfield hf = ramp(23, 17);
  for (int step : {1, 2, 5, 22}) {
    SCOPED_TRACE(step);
    const Heightfield o = ig::terrain::decimate_heightfield(hf, step);
    EXPECT_EQ(o.width, 22 / step + 1);
    EXPECT_EQ(o.height, 16 / step + 1);
    EXPECT_DOUBLE_EQ(o.spacing_x_m, 30.0 * step);
    EXPECT_DOUBLE_EQ(o.spacing_y_m, 20.0 * step);
    for (int l = 0; l < o.height; ++l)
      for (int k = 0; k < o.width; ++k) ASSERT_EQ(o.at(k, l), hf.at(k * step, l * step)) << k << "," << l;
    EXPECT_EQ(o.min_m, hf.at(0, 0));
  }
  EXPECT_THROW(ig::terrain::decimate_heightfield(hf, 0), std::invalid_argument);
}

TEST(HeightfieldOverview, SmallestStepThatFits) {
  EXPECT_EQ(ig::terrain::overview_step_for(4097, 4097, 4097), 1);
  EXPECT_EQ(ig::terrain::overview_step_for(20481, 20481, 4097), 5);   // 5 x 5 Sierra copies: 4097 exactly
  EXPECT_EQ(ig::terrain::overview_step_for(32769, 32769, 4097), 8);   // 4097 exactly
  EXPECT_EQ(ig::terrain::overview_step_for(4097, 100, 2049), 2);
  EXPECT_EQ(ig::terrain::overview_step_for(4098, 100, 2049), 2);      // 2049 samples, the last DEM column left out
  EXPECT_EQ(ig::terrain::overview_step_for(4099, 100, 2049), 3);      // 2 would give 2050
  for (int w : {2, 100, 4097, 20481, 32769})
    for (int side : {2, 1025, 4097}) {
      const int n = std::max(w, 7), s = ig::terrain::overview_step_for(w, 7, side);
      EXPECT_LE((n - 1) / s + 1, side) << w << " " << side;                     // fits
      if (s > 1) {
        EXPECT_GT((n - 1) / (s - 1) + 1, side) << w << " " << side;  // the smallest that fits
      }
    }
}

}  // namespace
