// back_faces_hidden: true only while the eye is above the surface under it
// (the highest corner of its cell, or the highest sample outside the grid).

#include <gtest/gtest.h>

#include <limits>

#include "terrain/back_faces_hidden.h"

namespace {

using ig::terrain::back_faces_hidden;
using ig::terrain::Heightfield;

Heightfield ramp_with_peak() {
  Heightfield hf;
  hf.width = 4;
  hf.height = 3;
  hf.spacing_x_m = 10.0;
  hf.spacing_y_m = 20.0;
  hf.heights = {0, 1, 2, 3,  //
                0, 1, 50, 3, //
                0, 1, 2, 3};
  hf.finalize_stats();
  return hf;
}

TEST(BackFacesHidden, AboveTheCellsHighestCorner) {
  const auto hf = ramp_with_peak();
  // Cell (1, 0) has corners 1, 2, 1, 50: the peak counts even where the
  // surface under the eye is lower.
  EXPECT_FALSE(back_faces_hidden(hf, {15.0, 5.0, 49.0}));
  EXPECT_TRUE(back_faces_hidden(hf, {15.0, 5.0, 50.5}));
  // Cell (0, 0): corners 0, 1, 0, 1.
  EXPECT_TRUE(back_faces_hidden(hf, {5.0, 5.0, 1.5}));
  EXPECT_FALSE(back_faces_hidden(hf, {5.0, 5.0, 0.5}));
}

TEST(BackFacesHidden, EdgesAndOutside) {
  const auto hf = ramp_with_peak();
  // On the far corner sample itself: the last cell, corners 50, 3, 2, 3.
  EXPECT_TRUE(back_faces_hidden(hf, {30.0, 40.0, 50.5}));
  EXPECT_FALSE(back_faces_hidden(hf, {30.0, 40.0, 49.0}));
  // Outside the grid only above the highest sample.
  EXPECT_FALSE(back_faces_hidden(hf, {-1.0, 5.0, 40.0}));
  EXPECT_TRUE(back_faces_hidden(hf, {-1.0, 5.0, 51.0}));
  EXPECT_FALSE(back_faces_hidden(hf, {5.0, 41.0, 49.0}));
}

TEST(BackFacesHidden, NonFiniteEyeKeepsBackFaces) {
  const auto hf = ramp_with_peak();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(back_faces_hidden(hf, {nan, 5.0, 100.0}));
  EXPECT_FALSE(back_faces_hidden(hf, {5.0, 5.0, std::numeric_limits<double>::infinity()}));
}

}  // namespace
