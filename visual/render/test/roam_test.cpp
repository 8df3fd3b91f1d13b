// Image tests of the ROAM baseline (render/roam_method) against the
// reference renderer, headless (EGL on llvmpipe), 320 x 240 frames of a
// 513 x 513 synthetic terrain: no holes at several views, a crack-free mesh
// at the same eyes, the knob sweep monotonic in triangles and error bound.
// Measured figures are printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "render/test/lod_view_checks.h"
#include "lod/roam_tessellator.h"
#include "render/roam_method.h"
#include "lod/test/lod_mesh_checks.h"

namespace {

using ig::render::RoamMethod;
using lod_views::kH;
using lod_views::World;

World& world() { return lod_views::shared_world(); }

TEST(Roam, NoHolesAgainstTheReferenceAtManyViews) {
  auto& w = world();
  RoamMethod roam(*w.scene, w.shader_dir);
  lod_views::expect_no_holes_at_per_frame_views(w, roam, 1, [&](const lod_views::View& v) {
    // The same eye without culling: the whole mesh is crack-free.
    ig::lod::RoamTessellator whole(w.hf);
    const auto sel = whole.select(v.camera.position, 2.0, ig::render::pixels_per_radian(v.camera, kH));
    EXPECT_EQ(lod_checks::watertight(sel.vertices, w.hf.width, w.hf.height), "") << v.name;
  });
}

TEST(Roam, KnobSweepGivesMoreTrianglesAndASmallerBound) {
  lod_views::expect_sweep_refines_down_to_the_floor(world(), "roam", "tau", 0.0);
}

TEST(Roam, RegisteredWithItsKnob) {
  lod_views::expect_registered_with_default_knob(world(), "roam", "tau_px", ig::render::RoamOptions{}.tau_px, 5, -1.0);
}

}  // namespace
