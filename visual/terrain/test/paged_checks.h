#pragma once
// What the paged-heights tests (paged_dem_test.cpp, paged_voids_test.cpp)
// check of a paged load against the whole load of the same file.

#include <gtest/gtest.h>

#include <string>

#include "terrain/height_pyramid.h"
#include "terrain/heightfield.h"
#include "terrain/heightfield_overview.h"
#include "terrain/paged_heights.h"

namespace ig::terrain::test {

// The paged load's overview is the whole load decimated by its step, and its
// height pyramid equals the whole load's from level `first_level` up (the
// levels below it come from the tiles as read). `where` leads every failure
// message.
inline void expect_same_overview_and_pyramid(const Heightfield& whole, const Heightfield& paged, int first_level,
                                             const std::string& where = "") {
  EXPECT_EQ(paged.paged->overview->heights, decimate_heightfield(whole, paged.paged->overview_step).heights) << where;
  const HeightPyramid pw(whole), pp(paged);
  ASSERT_EQ(pp.num_levels(), pw.num_levels()) << where;
  for (int l = first_level; l < pw.num_levels(); ++l)
    for (int j = 0; j < pw.level_height(l); ++j)
      for (int i = 0; i < pw.level_width(l); ++i) {
        ASSERT_EQ(pp.node(l, i, j).lo, pw.node(l, i, j).lo) << where << l << ":" << i << "," << j;
        ASSERT_EQ(pp.node(l, i, j).hi, pw.node(l, i, j).hi) << where << l << ":" << i << "," << j;
      }
}

}  // namespace ig::terrain::test
