#include "gl/twolevel_meshes.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "gl/work_counters.h"
#include "lod/twolevel_selection.h"

namespace ig::gl {

Level1SizeMeshes::Level1SizeMeshes(int n, int w, int stride) {
  // Walls: the square's perimeter twice (top and bottom vertex per edge sample).
  const std::vector<glm::ivec2> perimeter = lod::level1_perimeter(n);
  std::vector<std::int16_t> local;
  for (const auto& p : perimeter)
    for (int k = 0; k < 2; ++k) local.insert(local.end(), {std::int16_t(p.x), std::int16_t(p.y)});
  const std::vector<glm::vec2> wall_z(perimeter.size() * 2, glm::vec2(0.0f));
  std::vector<std::uint32_t> idx;
  const auto m = std::uint32_t(perimeter.size());
  for (std::uint32_t k = 0; k < m; ++k) {
    const std::uint32_t a = 2 * k, b = 2 * ((k + 1) % m);
    idx.insert(idx.end(), {a, b, b + 1, a, b + 1, a + 1});
  }
  wall_indices = GLsizei(idx.size());
  wall_bytes = GLsizeiptr(wall_z.size() * sizeof(glm::vec2));
  wall_local = create_buffer(local);
  wall_heights = create_buffer(wall_z, GL_DYNAMIC_STORAGE_BIT);
  wall_ibo = create_buffer(idx);
  wall_vao = create_vertex_array();
  glVertexArrayVertexBuffer(wall_vao.id(), 0, wall_local.id(), 0, 4);
  glVertexArrayVertexBuffer(wall_vao.id(), 1, wall_heights.id(), 0, sizeof(glm::vec2));
  glVertexArrayElementBuffer(wall_vao.id(), wall_ibo.id());
  vertex_attrib_int(wall_vao, 0, 2, GL_SHORT, 0, 0);
  vertex_attrib_float(wall_vao, 1, 2, GL_FLOAT, 0, 1);

  // Band ring: the grid grown by w on every side, minus Level1's square,
  // every `stride` samples.
  local.clear();
  idx.clear();
  const int side = (n - 1 + 2 * w) / stride + 1;
  for (int b = 0; b < side; ++b)
    for (int a = 0; a < side; ++a) {
      local.push_back(std::int16_t(-w + a * stride));
      local.push_back(std::int16_t(-w + b * stride));
    }
  auto v = [side](int a, int b) { return std::uint32_t(b * side + a); };
  for (int b = 0; b + 1 < side; ++b)
    for (int a = 0; a + 1 < side; ++a) {
      const int x = -w + a * stride, y = -w + b * stride;
      const bool inside = x >= 0 && y >= 0 && x + stride <= n - 1 && y + stride <= n - 1;
      if (inside) continue;
      idx.insert(idx.end(), {v(a, b), v(a + 1, b), v(a + 1, b + 1), v(a, b), v(a + 1, b + 1), v(a, b + 1)});
    }
  ring_indices = GLsizei(idx.size());
  ring_vbo = create_buffer(local);
  ring_ibo = create_buffer(idx);
  ring_vao = create_vertex_array();
  glVertexArrayVertexBuffer(ring_vao.id(), 0, ring_vbo.id(), 0, 4);
  glVertexArrayElementBuffer(ring_vao.id(), ring_ibo.id());
  vertex_attrib_int(ring_vao, 0, 2, GL_SHORT, 0, 0);
}

void Level1SizeMeshes::upload_wall_heights(const std::vector<glm::vec2>& wall_z, std::uint64_t version) {
  if (uploaded_wall_version_ == version) return;
  uploaded_wall_version_ = version;
  const GLsizeiptr bytes = std::min(wall_bytes, GLsizeiptr(wall_z.size() * sizeof(glm::vec2)));
  glNamedBufferSubData(wall_heights.id(), 0, bytes, wall_z.data());
  count_upload(std::uint64_t(bytes));
}

Level0Buffer::Level0Buffer(const lod::Level0Mesh& mesh, const std::vector<float>& lift) {
  std::vector<std::int32_t> samples;
  samples.reserve(mesh.samples.size() * 3);
  for (size_t v = 0; v < mesh.samples.size(); ++v) {
    std::int32_t bits = 0;
    std::memcpy(&bits, &lift[v], 4);
    samples.insert(samples.end(), {mesh.samples[v].x, mesh.samples[v].y, bits});
  }
  vbo = create_buffer(samples);
  ibo = create_buffer(mesh.indices);
  vao = create_vertex_array();
  glVertexArrayVertexBuffer(vao.id(), 0, vbo.id(), 0, 12);
  glVertexArrayElementBuffer(vao.id(), ibo.id());
  vertex_attrib_int(vao, 0, 2, GL_INT, 0, 0);
  vertex_attrib_float(vao, 1, 1, GL_FLOAT, 8, 0);
}

void BetaTemplate::update(int n, int band_w, bool gaussian) {
  if (tex_ && n_ == n && band_w_ == band_w) return;
  constexpr int kSize = 256;
  const double inner = 0.5 * (n - 1) / (0.5 * (n - 1) + band_w);  // Level1's half side / grown half side
  std::vector<float> beta(kSize * kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double qx = std::abs((x + 0.5) / kSize * 2.0 - 1.0), qy = std::abs((y + 0.5) / kSize * 2.0 - 1.0);
      const double t = std::clamp((std::max(qx, qy) - inner) / (1.0 - inner), 0.0, 1.0);
      const double g = std::exp(-4.5);
      beta[y * kSize + x] = float(gaussian ? (std::exp(-4.5 * t * t) - g) / (1.0 - g) : 1.0 - t);
    }
  if (!tex_) {
    tex_ = create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(tex_.id(), 1, GL_R16F, kSize, kSize);
    glTextureParameteri(tex_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(tex_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(tex_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(tex_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  glTextureSubImage2D(tex_.id(), 0, 0, 0, kSize, kSize, GL_RED, GL_FLOAT, beta.data());
  count_upload(std::uint64_t(beta.size() * sizeof(float)));
  n_ = n;
  band_w_ = band_w;
}

}  // namespace ig::gl
