// Image tests of the quadtree baseline (render/quadtree_method) against the
// reference renderer, headless (EGL on llvmpipe), 320 x 240 frames of a
// 513 x 513 synthetic terrain: no holes at several views, restricted levels
// and a crack-free mesh at the same eyes, the C1 sweep monotonic in
// triangles and error bound. Measured figures are printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "render/test/lod_view_checks.h"
#include "lod/quadtree_tessellator.h"
#include "render/quadtree_method.h"
#include "lod/test/lod_mesh_checks.h"

namespace {

using ig::render::QuadtreeMethod;
using lod_views::World;

World& world() { return lod_views::shared_world(); }

// Leaves sharing an edge differ by at most one level (cells inside the DEM).
bool levels_restricted(const ig::lod::QuadtreeTessellator& q, const ig::terrain::Heightfield& hf) {
  for (int cy = 0; cy < hf.height - 1; ++cy)
    for (int cx = 0; cx < hf.width - 1; ++cx) {
      const int l = q.leaf_level(cx, cy);
      if (cx + 1 < hf.width - 1 && std::abs(l - q.leaf_level(cx + 1, cy)) > 1) return false;
      if (cy + 1 < hf.height - 1 && std::abs(l - q.leaf_level(cx, cy + 1)) > 1) return false;
    }
  return true;
}

TEST(Quadtree, NoHolesAgainstTheReferenceAtManyViews) {
  auto& w = world();
  QuadtreeMethod quadtree(*w.scene, w.shader_dir);
  lod_views::expect_no_holes_at_per_frame_views(w, quadtree, 2, [&](const lod_views::View& v) {
    // This frame's quadtree (culled as drawn) keeps adjacent levels within
    // one; the same eye without culling gives a crack-free whole mesh.
    EXPECT_TRUE(levels_restricted(quadtree.tessellator(), w.hf)) << v.name;
    ig::lod::QuadtreeTessellator whole(w.hf);
    const auto sel = whole.select(v.camera.position, ig::render::QuadtreeOptions{}.c1, ig::render::QuadtreeOptions{}.c2);
    EXPECT_EQ(lod_checks::watertight(sel.vertices, w.hf.width, w.hf.height), "") << v.name;
  });
}

TEST(Quadtree, C1SweepGivesMoreTrianglesAndASmallerBound) {
  lod_views::expect_sweep_refines_down_to_the_floor(world(), "quadtree", "C1", 1e4);
}

TEST(Quadtree, RegisteredWithItsKnob) {
  lod_views::expect_registered_with_default_knob(world(), "quadtree", "C1", ig::render::QuadtreeOptions{}.c1, 6, 0.0);
}

}  // namespace
