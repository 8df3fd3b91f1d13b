// Level0 the band cannot reach is drawn with a program without the band's
// search (lod/band_ring.h, shaders/level0_no_band.frag): the picture must be
// the one drawing all of Level0 with the band's program gives, byte for
// byte (colour and depth), on views where the band shows, and the split
// must take part of Level0 off the band's program. Headless EGL on llvmpipe.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "lod_view_checks.h"

namespace {

TEST(TwoLevelBandSplit, Level0OutOfTheBandsReachGivesTheSamePicture) {
  auto& world = lod_views::shared_world();
  long long split_indices = 0, band_indices = 0;
  for (const auto& view : lod_views::views(world.hf)) {
    lod_views::Frame frames[2];
    for (int split = 0; split < 2; ++split) {
      ig::render::TwoLevelMethod method(*world.scene, world.shader_dir);
      method.set_band_split(split == 1);
      for (int k = 0; k < 3; ++k) lod_views::render(world, method, view.camera);  // Level1's size settles
      frames[split] = lod_views::render(world, method, view.camera);
      const auto& runs = method.selection().level0_runs;
      if (split == 1) {
        split_indices += (long long)runs[2].indices();
        band_indices += (long long)runs[0].indices();
      } else {
        EXPECT_EQ(runs[2].indices(), 0u) << view.name << ": the split is off";
      }
    }
    long long differing = 0;
    for (size_t p = 0; p < frames[0].depth.size(); ++p)
      differing += frames[0].depth[p] != frames[1].depth[p] ||
                   std::memcmp(&frames[0].rgba[4 * p], &frames[1].rgba[4 * p], 4) != 0;
    std::printf("%-8s: %lld pixels differ\n", view.name.c_str(), differing);
    EXPECT_EQ(differing, 0) << view.name;
  }
  std::printf("Level0 indices over the views: %lld with the band's program, %lld without\n", band_indices,
              split_indices);
  EXPECT_GT(split_indices, 0) << "no Level0 left the band's program: the split buys nothing";
  EXPECT_GT(band_indices, 0) << "no Level0 kept the band's program on these views";
}

}  // namespace
