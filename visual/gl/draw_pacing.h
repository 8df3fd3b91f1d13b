#pragma once
// Paces triangle draws on a software rasterizer so its memory does not
// depend on the heaviest frame of the run.
//
// llvmpipe bins triangles into "scenes" (at most 9 MB of bin data each) that
// its worker threads rasterize while the next scene fills; when binning runs
// ahead it opens another scene. A scene keeps its bin memory until the
// driver reuses it, and it reuses the lowest-numbered idle scene first, so
// the scenes only one heavy frame needed stay full for the rest of the run
// (measured: one 1.36 M-triangle frame left 43 MB held). With pacing on,
// every kPacedTriangles triangles the draws fence the chunk and wait until
// the chunk before it is done: the scenes in flight no longer depend on the
// frame's weight, and the rasterizer still has a chunk to work on while the
// next is binned. It costs the heaviest frames about 14 % on llvmpipe;
// chunks of 131 072 and 262 144 triangles timed the same, and 524 288 held
// as much as no pacing (docs/results.md).
// On a GPU a mid-frame wait would stall its pipeline and no such growth was
// measured, so pacing is on only on software rasterizers.
//
// Every terrain draw goes through these calls (all methods alike); each
// GL draw call made is counted (gl/work_counters.h).

#include <epoxy/gl.h>

#include <string>
#include <vector>

namespace ig::gl {

constexpr long long kPacedTriangles = 65536;

// Per thread (the thread's current context). gl::finish() ends a frame's pacing.
void set_draw_pacing(bool on);
bool draw_pacing();
// Whether a renderer (GL_RENDERER) is a software rasterizer that needs pacing.
bool needs_draw_pacing(const std::string& renderer);

// glDrawElements(GL_TRIANGLES) of `count` indices from index `first`.
void draw_indexed_triangles(GLenum index_type, GLsizei first, GLsizei count);
// glDrawArrays(GL_TRIANGLES) of `count` vertices from `first`.
void draw_triangle_list(GLint first, GLsizei count);
// glMultiDrawElements(GL_TRIANGLES) of 32-bit index runs (counts, byte offsets).
void draw_indexed_runs(const std::vector<GLsizei>& counts, const std::vector<const void*>& offsets);

// Deletes the pacing fences (everything issued has finished).
void end_draw_pacing();

}  // namespace ig::gl
