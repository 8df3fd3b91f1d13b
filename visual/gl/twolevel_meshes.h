#pragma once
// The two-level method's GL geometry (docs/twolevel.md): Level0's static
// buffer, and per Level1 size the seam walls and the transition band's ring.

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "gl/gl_objects.h"
#include "lod/roam_level0_mesh.h"

namespace ig::gl {

// Walls around Level1's square (they close the step between Level1's edge
// and Level0's coarser surface there, whichever is higher) and the band's
// ring, for one (N, w_trans) pair. The walls' heights change with the
// square and the view (lod::TwoLevelSelection::wall_z, uploaded by
// upload_wall_heights only when its version differs from the last one here).
struct Level1SizeMeshes {
  VertexArray wall_vao;
  Buffer wall_local, wall_heights, wall_ibo;
  GLsizei wall_indices = 0;
  GLsizeiptr wall_bytes = 0;
  VertexArray ring_vao;
  Buffer ring_vbo, ring_ibo;
  GLsizei ring_indices = 0;

  // stride: the ring's sample step (w and n - 1 are multiples of it).
  Level1SizeMeshes(int n, int w, int stride);
  void upload_wall_heights(const std::vector<glm::vec2>& wall_z, std::uint64_t version);

 private:
  std::optional<std::uint64_t> uploaded_wall_version_;
};

// Level0's static buffer: per vertex its sample index (2 x i32) and lift (f32).
struct Level0Buffer {
  VertexArray vao;
  Buffer vbo, ibo;
  Level0Buffer(const lod::Level0Mesh& mesh, const std::vector<float>& lift);
};

// The paper's 256 x 256 weight template over the grown square: 1 over
// Level1, falling to 0 across the band (linear or Gaussian); uploaded again
// only when (n, band_w) changes.
class BetaTemplate {
 public:
  void update(int n, int band_w, bool gaussian);
  const Texture& texture() const { return tex_; }

 private:
  Texture tex_;
  int n_ = 0, band_w_ = 0;
};

}  // namespace ig::gl
