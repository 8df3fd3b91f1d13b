// Pipelined frames (FrameRenderer::set_pipelined, gl::FrameFence): a frame
// issued while the one before is still being drawn, with no stage waiting
// for the GL, draws the picture a finished frame draws; it reads no
// pipeline statistics (which would wait) and still counts its draw calls.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "gl/frame_fence.h"
#include "render/frame_renderer.h"
#include "render/test/lod_view_checks.h"
#include "session/view_step.h"

namespace {

using lod_views::camera_at;
using lod_views::World;

struct Drawn {
  std::vector<std::uint8_t> rgba;
  std::vector<float> depth;
  ig::render::ViewResult result;
};

// The frames along `cameras`, the last one read back. Pipelined with
// `wait_between` false: each frame is issued right behind the one before
// (two in flight); true: each issued after the one before is done.
Drawn fly(World& w, const std::string& method_name, const std::vector<ig::render::Camera>& cameras, bool pipelined,
          bool wait_between) {
  auto method = ig::render::make_method(method_name, *w.scene, w.shader_dir, {}, std::nullopt);
  ig::render::FrameRenderer renderer(*w.scene, *method, w.shader_dir);
  renderer.set_pipelined(pipelined);
  Drawn d;
  std::vector<ig::gl::FrameFence> fences;
  for (const auto& c : cameras) {
    d.result = ig::session::render_view(*w.scene, renderer, c, *w.target);
    fences.push_back(ig::gl::FrameFence::after_issued_work());
    if (wait_between) fences.back().wait();
  }
  fences.back().wait();
  EXPECT_TRUE(fences.back().done());
  d.rgba = w.target->read_rgba();
  d.depth = w.target->read_depth();
  return d;
}

class PipelinedFrames : public ::testing::Test {
 protected:
  static World& world() {
    static World w(257, 4);
    return w;
  }
  std::vector<ig::render::Camera> path() {
    const auto& hf = world().hf;
    const double ex = hf.extent_x_m(), ey = hf.extent_y_m();
    return {camera_at(hf, 0.3 * ex, 0.3 * ey, 150.0, 40.0, -8.0), camera_at(hf, 0.32 * ex, 0.31 * ey, 160.0, 45.0, -9.0),
            camera_at(hf, 0.34 * ex, 0.32 * ey, 170.0, 50.0, -10.0)};
  }
};

TEST_F(PipelinedFrames, FramesInFlightDrawTheFinishedPicture) {
  for (const std::string m : {"cdlod", "chunked", "geomipmap"}) {
    const Drawn finished = fly(world(), m, path(), false, true);
    const Drawn pipelined = fly(world(), m, path(), true, false);
    EXPECT_EQ(pipelined.rgba, finished.rgba) << m;
    EXPECT_EQ(pipelined.depth, finished.depth) << m;
    // No statistics read while frames are in flight; draw calls still counted.
    EXPECT_GT(finished.result.total.vs_invocations, 0u) << m;
    EXPECT_EQ(pipelined.result.total.vs_invocations, 0u) << m;
    EXPECT_EQ(pipelined.result.total.draw_calls, finished.result.total.draw_calls) << m;
    EXPECT_GT(pipelined.result.total.draw_calls, 0u) << m;
  }
}

// Two-level sizes Level1 from the last frame's coverage query, which a
// frame in flight may not have answered yet (the size is then kept a frame):
// with each frame done before the next, the stages drawn without waits
// draw the same picture.
TEST_F(PipelinedFrames, TwoLevelWithoutStageWaitsDrawsTheFinishedPicture) {
  const Drawn finished = fly(world(), "twolevel", path(), false, true);
  const Drawn pipelined = fly(world(), "twolevel", path(), true, true);
  EXPECT_EQ(pipelined.rgba, finished.rgba);
  EXPECT_EQ(pipelined.depth, finished.depth);
  EXPECT_EQ(pipelined.result.method.triangles, finished.result.method.triangles);
}

TEST(FrameFence, AnEmptyFenceIsDone) {
  const ig::gl::FrameFence none;
  EXPECT_TRUE(none.done());
  none.wait();  // returns at once
}

}  // namespace
