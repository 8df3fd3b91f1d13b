#include "gl/draw_pacing.h"

#include <algorithm>
#include <cstdint>

#include "gl/work_counters.h"

namespace ig::gl {
namespace {

struct Pacing {
  bool on = false;
  long long since_fence = 0;  // triangles drawn since the last fence
  GLsync last = nullptr;  // the fence after the last chunk
};

Pacing& pacing() {
  thread_local Pacing p;
  return p;
}

// After drawing `triangles`: at a chunk's end, fences it and waits for the
// chunk before it, so the rasterizer works on one chunk while the next is
// binned, and no more.
void paced(long long triangles) {
  Pacing& p = pacing();
  if (!p.on) return;
  p.since_fence += triangles;
  if (p.since_fence < kPacedTriangles) return;
  p.since_fence = 0;
  const GLsync fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  if (p.last) {
    constexpr GLuint64 kSecond = 1000000000;
    while (glClientWaitSync(p.last, GL_SYNC_FLUSH_COMMANDS_BIT, kSecond) == GL_TIMEOUT_EXPIRED) {
    }
    glDeleteSync(p.last);
  }
  p.last = fence;
}

std::size_t index_bytes(GLenum index_type) {
  return index_type == GL_UNSIGNED_INT ? 4 : index_type == GL_UNSIGNED_SHORT ? 2 : 1;
}

// Pieces of whole triangles, at most a chunk each while pacing.
template <typename Draw>
void in_pieces(GLsizei count, Draw draw) {
  const GLsizei piece = pacing().on ? GLsizei(3 * kPacedTriangles) : std::max<GLsizei>(count, 1);
  for (GLsizei first = 0; first < count; first += piece) {
    const GLsizei n = std::min(piece, count - first);
    draw(first, n);
    count_draw();
    paced(n / 3);
  }
}

}  // namespace

void set_draw_pacing(bool on) {
  // Fences left by a context that is gone are dropped, not deleted.
  pacing() = Pacing{};
  pacing().on = on;
}

bool draw_pacing() { return pacing().on; }

bool needs_draw_pacing(const std::string& renderer) {
  return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos;
}

void draw_indexed_triangles(GLenum index_type, GLsizei first, GLsizei count) {
  in_pieces(count, [&](GLsizei from, GLsizei n) {
    glDrawElements(GL_TRIANGLES, n, index_type,
                   reinterpret_cast<const void*>(std::size_t(first + from) * index_bytes(index_type)));
  });
}

void draw_triangle_list(GLint first, GLsizei count) {
  in_pieces(count, [&](GLsizei from, GLsizei n) { glDrawArrays(GL_TRIANGLES, first + from, n); });
}

void draw_indexed_runs(const std::vector<GLsizei>& counts, const std::vector<const void*>& offsets) {
  // Consecutive runs up to a chunk of triangles per call while pacing (a
  // longer run is one call of its own).
  const long long piece = pacing().on ? 3 * kPacedTriangles : -1;
  std::size_t begin = 0;
  while (begin < counts.size()) {
    std::size_t end = begin;
    long long indices = 0;
    while (end < counts.size() && (piece < 0 || end == begin || indices + counts[end] <= piece)) indices += counts[end++];
    glMultiDrawElements(GL_TRIANGLES, counts.data() + begin, GL_UNSIGNED_INT, offsets.data() + begin,
                        GLsizei(end - begin));
    count_draw();
    paced(indices / 3);
    begin = end;
  }
}

void end_draw_pacing() {
  Pacing& p = pacing();
  if (p.last) glDeleteSync(p.last);
  p.last = nullptr;
  p.since_fence = 0;
}

}  // namespace ig::gl
