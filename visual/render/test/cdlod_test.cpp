// CDLOD (visual/render/cdlod_method.*) rendered headless against the
// reference at several views of a synthetic terrain: no holes (the morph
// closes every edge between LODs; the CPU check of that is
// tests/unit/cdlod_selection_test), the knob trades triangles for error, the
// claimed error bound is sane, and DEMs of odd sizes render.
#include <gtest/gtest.h>

#include <cstdio>

#include "render/test/lod_view_checks.h"
#include "render/cdlod_method.h"

namespace {

using ig::render::CdlodMethod;
using lod_views::Frame;

class CdlodTest : public lod_views::ReferenceFramesTest {};

TEST_F(CdlodTest, NoHolesAgainstTheReference) {
  // A short finest range, so every view mixes several LODs and morph zones.
  CdlodMethod method(*world_->scene, world_->shader_dir, 32.0);
  lod_views::expect_every_view_without_holes(
      *world_, *reference_, method, "cdlod", [](const std::string& view, const Frame& f) {
        std::printf("cdlod %-8s lods %.0f..%.0f\n", view.c_str(), f.stats.columns[2].second, f.stats.columns[3].second);
        if (view != "down") {
          EXPECT_GT(f.stats.columns[3].second, f.stats.columns[2].second) << "several LODs";
        }
      });
}

// Each piece's LOD respects the ranges: every point drawn at LOD k lies
// beyond range(k - 1) (pieces are never too coarse for their distance).
TEST_F(CdlodTest, PiecesRespectTheirLodRanges) {
  CdlodMethod method(*world_->scene, world_->shader_dir, 64.0);
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
  const auto views = lod_views::views(world_->hf);
  for (const auto& v : {views[0], views[1]}) {
    lod_views::SweepChecks sweep(v.name, "range");
    for (double range : ig::render::knob_sweep("cdlod")) {
      CdlodMethod method(*world_->scene, world_->shader_dir, range);
      const Frame f = lod_views::render(*world_, method, v.camera);
      std::printf("cdlod %-8s lod0_range %4.0f  triangles %8lld  bound %7.2f px  pieces %3.0f  lod %.2f ms\n",
                  v.name.c_str(), range, f.stats.triangles, f.bound_px,
                  f.stats.columns[0].second + f.stats.columns[1].second, f.lod_ms);
      sweep.add(f, range);
    }
    sweep.finish();
  }
}

TEST_F(CdlodTest, RegisteredWithItsKnob) {
  ASSERT_NO_FATAL_FAILURE(lod_views::expect_registered_with_knob(*world_, "cdlod", "lod0_range", 200.0, true));
  EXPECT_THROW(CdlodMethod(*world_->scene, world_->shader_dir, 0.0), std::invalid_argument);
}

TEST_F(CdlodTest, DemsOfAnySizeRenderWithoutHoles) {
  lod_views::expect_odd_sized_dems_render_without_holes(
      *world_, [](const auto& scene) { return std::make_unique<CdlodMethod>(scene, world_->shader_dir, 8.0); });
}

}  // namespace
