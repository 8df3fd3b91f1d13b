// Draw pacing (gl/draw_pacing.h): on a software rasterizer, a frame far
// heavier than the rest leaves no driver memory held after it; the pieces
// a paced draw is cut into draw exactly the picture one call draws, and
// each is counted as the GL draw call it is.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "gl/draw_pacing.h"
#include "gl/frame_state.h"
#include "gl/gl_context.h"
#include "gl/grid_mesh.h"
#include "gl/render_target.h"
#include "gl/shader_program.h"
#include "gl/work_counters.h"
#include "session/process_memory.h"

namespace {

// A grid of n x n quads filling the target, with as many varyings as the
// terrain programs interpolate (the driver bins every one per triangle).
ig::gl::ShaderProgram grid_program() {
  const auto dir = std::filesystem::temp_directory_path() / "ig_draw_pacing_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "grid.vert") << R"(#version 450
layout(location = 0) in ivec2 a_sample;
uniform float u_quads;
out vec4 v_a, v_b, v_c, v_d;
void main() {
  vec2 p = vec2(a_sample) / u_quads;
  v_a = vec4(p, 0.5, 1.0); v_b = vec4(p.yx, 0.25, 1.0); v_c = v_a * 0.5; v_d = v_b * 0.5;
  gl_Position = vec4(p * 2.0 - 1.0, 0.5, 1.0);
}
)";
  std::ofstream(dir / "grid.frag") << R"(#version 450
in vec4 v_a, v_b, v_c, v_d;
out vec4 o_color;
void main() { o_color = vec4(v_a.x, v_b.x, v_c.y + v_d.y, 1.0); }
)";
  return ig::gl::ShaderProgram(dir.string(), "grid.vert", "grid.frag");
}

struct Frame {
  std::vector<std::uint8_t> pixels;
  std::uint64_t draw_calls = 0;
};

Frame draw_grid(const ig::gl::RenderTarget& target, const ig::gl::ShaderProgram& program, const ig::gl::GridMesh& mesh,
                int repeats = 1) {
  target.bind();
  ig::gl::begin_frame(false);
  program.use();
  program.set("u_quads", float(mesh.quads_per_side()));
  const std::uint64_t calls = ig::gl::work_tally().draw_calls;
  for (int k = 0; k < repeats; ++k) mesh.draw();
  ig::gl::finish();
  return {target.read_rgba(), ig::gl::work_tally().draw_calls - calls};
}

double heap_in_use_mb() { return ig::session::process_memory().value("heap_in_use_mb", 0.0); }

TEST(DrawPacing, OnlySoftwareRasterizersArePaced) {
  EXPECT_TRUE(ig::gl::needs_draw_pacing("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_TRUE(ig::gl::needs_draw_pacing("softpipe"));
  EXPECT_FALSE(ig::gl::needs_draw_pacing("NVIDIA H200/PCIe/SSE2"));
  EXPECT_FALSE(ig::gl::needs_draw_pacing("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.6, DRM 3.52)"));
}

TEST(DrawPacing, PiecesDrawThePictureOneCallDraws) {
  const auto context = ig::gl::create_headless_context();
  const ig::gl::RenderTarget target(160, 120);
  const auto program = grid_program();
  const ig::gl::GridMesh mesh(256);  // 131 072 triangles: two paced pieces
  ig::gl::set_draw_pacing(false);
  const Frame whole = draw_grid(target, program, mesh);
  ig::gl::set_draw_pacing(true);
  const Frame paced = draw_grid(target, program, mesh);
  ig::gl::set_draw_pacing(ig::gl::needs_draw_pacing(context->gl_renderer()));
  EXPECT_EQ(whole.draw_calls, 1u);
  EXPECT_EQ(paced.draw_calls, std::uint64_t(2 * 256 * 256 / ig::gl::kPacedTriangles));
  ASSERT_EQ(whole.pixels.size(), paced.pixels.size());
  EXPECT_TRUE(whole.pixels == paced.pixels);
  EXPECT_TRUE(ig::gl::no_gl_error());
}

TEST(DrawPacing, TheDriverHoldsNoMoreAfterAHeavierFrame) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "A sanitizer's allocator replaces malloc: the C library's heap figures stay empty";
#endif
  const auto context = ig::gl::create_headless_context();
  if (!ig::gl::needs_draw_pacing(context->gl_renderer()))
    GTEST_SKIP() << "Not a software rasterizer (" << context->gl_renderer() << "): nothing is paced";
  ASSERT_TRUE(ig::gl::draw_pacing()) << "the context turns pacing on for " << context->gl_renderer();
  const ig::gl::RenderTarget target(320, 240);
  const auto program = grid_program();
  const ig::gl::GridMesh light(64), heavy(1024);  // 8 192 and 2 097 152 triangles
  // After a frame of `repeats` heavy grids and light frames enough to
  // settle, the heap in use.
  auto held_after = [&](int repeats) {
    if (repeats > 0) draw_grid(target, program, heavy, repeats);
    for (int k = 0; k < 8; ++k) draw_grid(target, program, light);
    return heap_in_use_mb();
  };
  const double steady = held_after(0);
  const double after_heavy = held_after(1);
  const double after_heavier = held_after(4);  // 8.4 M triangles
  ig::gl::set_draw_pacing(false);
  const double unpaced = held_after(4);
  ig::gl::set_draw_pacing(true);
  std::printf("heap in use: %.1f MB steady; paced %+.1f MB after 2.1 M triangles, %+.1f MB more after 8.4 M; "
              "unpaced %+.1f MB more after 8.4 M\n",
              steady, after_heavy - steady, after_heavier - after_heavy, unpaced - after_heavier);
  // Paced, what the driver holds after a heavy frame is two chunks' bins at
  // most, whatever the frame's weight. Which frame first has two chunks in
  // flight depends on the rasterizer threads' timing (on a loaded machine
  // the 2.1 M-triangle frame held +0.0 MB and the 8.4 M one +13.2 MB; idle,
  // the other way round), so both are held to the bound, not to each other.
  EXPECT_LT(after_heavy - steady, 16.0);
  EXPECT_LT(after_heavier - steady, 16.0);
}

}  // namespace
