// Chunked LOD (visual/render/chunked_method.*) rendered headless against the
// reference at several views of a synthetic terrain: no holes, skirts deep
// enough to close every crack between the chunks drawn (checked on the CPU),
// the knob trades triangles for error, the claimed error bound holds the
// tolerance, and DEMs of odd sizes render.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "render/test/method_frames_fixture.h"
#include "render/chunked_method.h"

namespace {

using ig::render::ChunkedMethod;
using lod_views::Frame;

class ChunkedTest : public lod_views::MethodFramesTest<ChunkedMethod> {};

TEST_F(ChunkedTest, NoHolesAgainstTheReference) {
  expect_every_view_without_holes(1.0, "chunked", [](const std::string&, const Frame&) {});
}

// The height of a chunk's mesh edge at sample t along a side (the edge is
// linear between the chunk's vertices, clamped onto the DEM as drawn).
double edge_height(const ig::terrain::Heightfield& hf, const ig::lod::ChunkNode& n, bool vertical, int line, int t) {
  const int first = vertical ? n.j0 : n.i0, last = vertical ? hf.height - 1 : hf.width - 1;
  const int q = std::min((t - first) / n.stride, ig::lod::kChunkQuads - 1);
  const int a = std::min(first + q * n.stride, last), b = std::min(first + (q + 1) * n.stride, last);
  const double ha = vertical ? hf.at(line, a) : hf.at(a, line), hb = vertical ? hf.at(line, b) : hf.at(b, line);
  return b == a ? ha : ha + (hb - ha) * double(t - a) / double(b - a);
}

// CPU crack check: along every shared edge of two drawn chunks, at every DEM
// sample, the chunk whose edge is higher there hangs its skirt at least down
// to the other's edge, so the gap between them is closed.
TEST_F(ChunkedTest, SkirtsCloseEveryGapBetweenDrawnChunks) {
  const auto& hf = world_->hf;
  int shared = 0, mixed = 0;
  long long uncovered = 0;
  std::string first_uncovered;
  double widest_gap = 0.0;
  for (double tau : {4.0, 1.0}) {
    auto method = make(tau);
    for (const auto& v : lod_views::views(hf)) {
      method.update(v.camera);
      const auto& drawn = method.drawn();
      for (const auto& A : drawn)
        for (const auto& B : drawn) {
          const auto &a = method.tree().node(A.node), &b = method.tree().node(B.node);
          for (int vertical = 0; vertical < 2; ++vertical) {
            const bool vert = vertical == 1;
            // A's east (north) side on B's west (south) side.
            const int line = vert ? a.i0 + a.size() : a.j0 + a.size();
            if (line != (vert ? b.i0 : b.j0) || line >= (vert ? hf.width - 1 : hf.height - 1)) continue;
            const int last = (vert ? hf.height : hf.width) - 1;
            const int from = std::max(vert ? a.j0 : a.i0, vert ? b.j0 : b.i0);
            const int to = std::min({(vert ? a.j0 : a.i0) + a.size(), (vert ? b.j0 : b.i0) + b.size(), last});
            if (from >= to) continue;
            ++shared;
            mixed += a.level != b.level;
            for (int t = from; t <= to; ++t) {
              const double ha = edge_height(hf, a, vert, line, t), hb = edge_height(hf, b, vert, line, t);
              widest_gap = std::max(widest_gap, std::abs(ha - hb));
              const bool closed = ha > hb ? A.skirt_bottom_m <= hb : B.skirt_bottom_m <= ha;
              if (!closed && uncovered++ == 0)
                first_uncovered = "tau " + std::to_string(tau) + ", view " + v.name + ", line " +
                                  std::to_string(line) + ", sample " + std::to_string(t);
            }
          }
        }
    }
  }
  std::printf("chunked: %d shared edges (%d between levels), widest gap %.1f m\n", shared, mixed, widest_gap);
  EXPECT_EQ(uncovered, 0) << "first gap left open: " << first_uncovered;
  EXPECT_GT(mixed, 20) << "the check must see edges between different levels";
  EXPECT_GT(widest_gap, 1.0) << "and real gaps to close";
}

TEST_F(ChunkedTest, SmallerTauMeansMoreTrianglesAndASmallerClaimedError) {
  expect_knob_sweep("chunked", "tau", [](const lod_views::View& v, double tau, const Frame& f, const ChunkedMethod&) {
    std::printf("chunked %-8s tau %5.2f px  triangles %8lld  bound %7.2f px  chunks %3.0f  lod %.2f ms\n",
                v.name.c_str(), tau, f.stats.triangles, f.bound_px, f.stats.columns[0].second, f.lod_ms);
    EXPECT_LE(f.bound_px, tau + 1e-9) << "a drawn chunk is within tau or a leaf (exact)";
  });
}

TEST_F(ChunkedTest, RegisteredWithItsKnob) {
  ASSERT_NO_FATAL_FAILURE(lod_views::expect_registered_with_knob(*world_, "chunked", "tau_px", 6.0, false));
  EXPECT_THROW(make(-1.0), std::invalid_argument);
}

TEST_F(ChunkedTest, DemsOfAnySizeRenderWithoutHoles) {
  lod_views::expect_odd_sized_dems_render_without_holes(*world_, maker(1.0));
}

}  // namespace
