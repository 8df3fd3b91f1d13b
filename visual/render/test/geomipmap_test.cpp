// GeoMipMapping (visual/render/geomipmap_method.*) rendered headless against
// the reference at several views of a synthetic terrain: no holes, stitched
// neighbours, the knob trades triangles for error, the claimed error bound
// is sane, and DEMs of odd sizes render.
#include <gtest/gtest.h>

#include <cstdio>

#include "render/test/method_frames_fixture.h"
#include "render/geomipmap_method.h"

namespace {

using ig::render::GeoMipMapMethod;
using lod_views::Frame;

class GeoMipMapTest : public lod_views::MethodFramesTest<GeoMipMapMethod> {};

TEST_F(GeoMipMapTest, NoHolesAgainstTheReference) {
  expect_every_view_without_holes(1.0, "geomipmap", [](const std::string&, const Frame& f) {
    EXPECT_EQ(f.stats.passes, "terrain+shade+sky");
  });
}

// CPU side of the crack check on the live selection: every pair of drawn
// neighbours draws its shared side at one stride (the coarser level's), and
// a stitched side is never finer than the block's own level.
TEST_F(GeoMipMapTest, DrawnNeighboursAgreeOnTheirSharedSide) {
  auto method = make(1.0);
  int stitched = 0, pairs = 0;
  for (const auto& v : lod_views::views(world_->hf)) {
    lod_views::render(*world_, method, v.camera);
    const auto& blocks = method.blocks();
    std::vector<const GeoMipMapMethod::DrawnBlock*> at(blocks.blocks().size(), nullptr);
    for (const auto& d : method.drawn()) at[size_t(d.by) * blocks.blocks_x() + d.bx] = &d;
    for (const auto& d : method.drawn()) {
      stitched += d.config.stitched();
      for (int s : d.config.side_level) EXPECT_GE(s, d.config.level);
      if (d.bx + 1 < blocks.blocks_x()) {
        if (const auto* e = at[size_t(d.by) * blocks.blocks_x() + d.bx + 1]) {
          EXPECT_EQ(d.config.side_level[ig::lod::kEast], e->config.side_level[ig::lod::kWest]);
          EXPECT_EQ(d.config.side_level[ig::lod::kEast], std::max(d.config.level, e->config.level));
          ++pairs;
        }
      }
      if (d.by + 1 < blocks.blocks_y()) {
        if (const auto* n = at[size_t(d.by + 1) * blocks.blocks_x() + d.bx]) {
          EXPECT_EQ(d.config.side_level[ig::lod::kNorth], n->config.side_level[ig::lod::kSouth]);
          ++pairs;
        }
      }
    }
  }
  EXPECT_GT(pairs, 100);
  EXPECT_GT(stitched, 10) << "the views must exercise stitching";
}

TEST_F(GeoMipMapTest, SmallerTauMeansMoreTrianglesAndASmallerClaimedError) {
  expect_knob_sweep("geomipmap", "tau",
                    [](const lod_views::View& v, double tau, const Frame& f, const GeoMipMapMethod& method) {
                      std::printf("geomipmap %-8s tau %5.2f px  triangles %8lld  bound %7.2f px  lod %.2f ms\n",
                                  v.name.c_str(), tau, f.stats.triangles, f.bound_px, f.lod_ms);
                      // Unstitched blocks meet the tolerance by construction.
                      const double ppr = ig::render::pixels_per_radian(v.camera, lod_views::kH);
                      for (const auto& d : method.drawn())
                        if (!d.config.stitched()) {
                          EXPECT_LE(d.error_m / std::max(d.distance_m, v.camera.near_m) * ppr, tau + 1e-9);
                        }
                    });
}

TEST_F(GeoMipMapTest, RegisteredWithItsKnob) {
  ASSERT_NO_FATAL_FAILURE(lod_views::expect_registered_with_knob(*world_, "geomipmap", "tau_px", 3.5, false));
  EXPECT_THROW(make(0.0), std::invalid_argument);
  EXPECT_THROW(make(std::nan("")), std::invalid_argument);
}

TEST_F(GeoMipMapTest, DemsOfAnySizeRenderWithoutHoles) {
  lod_views::expect_odd_sized_dems_render_without_holes(
      *world_, maker(1.0), [](const Frame& f, const ig::terrain::Heightfield& hf) {
        EXPECT_LE(f.stats.triangles, 2LL * (hf.width - 1) * (hf.height - 1)) << hf.source;
      });
}

}  // namespace
