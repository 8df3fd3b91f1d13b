// CDLOD (visual/render/cdlod_method.*) rendered headless against the
// reference at several views of a synthetic terrain: no holes (the morph
// closes every edge between LODs; the CPU check of that is
// tests/unit/cdlod_selection_test), the knob trades triangles for error, the
// claimed error bound is sane, and DEMs of odd sizes render.
#include <gtest/gtest.h>

#include <cstdio>

#include "render/test/method_frames_fixture.h"
#include "render/cdlod_method.h"

namespace {

using ig::render::CdlodMethod;
using lod_views::Frame;

class CdlodTest : public lod_views::MethodFramesTest<CdlodMethod> {};

TEST_F(CdlodTest, NoHolesAgainstTheReference) {
  // A short finest range, so every view mixes several LODs and morph zones.
  expect_every_view_without_holes(32.0, "cdlod", [](const std::string& view, const Frame& f) {
    std::printf("cdlod %-8s lods %.0f..%.0f\n", view.c_str(), f.stats.columns[2].second, f.stats.columns[3].second);
    if (view != "down") {
      EXPECT_GT(f.stats.columns[3].second, f.stats.columns[2].second) << "several LODs";
    }
  });
}

// Each piece's LOD respects the ranges: every point drawn at LOD k lies
// beyond range(k - 1) (pieces are never too coarse for their distance).
TEST_F(CdlodTest, PiecesRespectTheirLodRanges) {
  auto method = make(64.0);
  for (const auto& v : lod_views::views(world_->hf)) {
    method.update(v.camera);
    ASSERT_FALSE(method.areas().empty()) << v.name;
    for (const auto& a : method.areas()) {
      const auto& n = method.tree().node(a.node);
      EXPECT_EQ(a.lod, method.tree().depth() - n.level);
      glm::dvec3 lo, hi;
      if (a.quadrant < 0) {
        method.tree().box(n, lo, hi);
      } else {
        method.tree().quadrant_box(n, a.quadrant, lo, hi);
      }
      if (a.lod > 0) {
        EXPECT_GT(ig::lod::box_distance(v.camera.position, lo, hi), method.ranges().range(a.lod - 1));
      }
    }
  }
}

TEST_F(CdlodTest, LargerRangeMeansMoreTrianglesAndASmallerClaimedError) {
  expect_knob_sweep("cdlod", "range", [](const lod_views::View& v, double range, const Frame& f, const CdlodMethod&) {
    std::printf("cdlod %-8s lod0_range %4.0f  triangles %8lld  bound %7.2f px  pieces %3.0f  lod %.2f ms\n",
                v.name.c_str(), range, f.stats.triangles, f.bound_px,
                f.stats.columns[0].second + f.stats.columns[1].second, f.lod_ms);
  });
}

TEST_F(CdlodTest, RegisteredWithItsKnob) {
  ASSERT_NO_FATAL_FAILURE(lod_views::expect_registered_with_knob(*world_, "cdlod", "lod0_range", 200.0, true));
  EXPECT_THROW(make(0.0), std::invalid_argument);
}

TEST_F(CdlodTest, DemsOfAnySizeRenderWithoutHoles) {
  lod_views::expect_odd_sized_dems_render_without_holes(*world_, maker(8.0));
}

}  // namespace
