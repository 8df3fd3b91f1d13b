#include "render/sample_triangle_stream.h"

#include <algorithm>
#include <cmath>

#include "gl/work_counters.h"

namespace ig::render {

SampleTriangleStream::SampleTriangleStream(const TerrainScene& scene, const std::string& shader_dir)
    : program_(shader_dir, "level0.vert", scene.shading_stages({"terrain.frag"})) {
  vbo_ = gl::create_buffer();
  vao_ = gl::create_vertex_array();
  glVertexArrayVertexBuffer(vao_.id(), 0, vbo_.id(), 0, sizeof(glm::u16vec2));
  gl::vertex_attrib_int(vao_, 0, 2, GL_UNSIGNED_SHORT, 0, 0);  // -> ivec2 a_sample
}

void SampleTriangleStream::draw(const std::vector<glm::u16vec2>& vertices, const TerrainScene& scene,
                                const Camera& camera) {
  if (vertices.empty()) return;
  const GLsizeiptr bytes = GLsizeiptr(vertices.size() * sizeof(glm::u16vec2));
  // Orphan the old storage (the GPU may still read it) rather than wait for
  // it; grow geometrically so steady frames never reallocate on our side.
  if (bytes > capacity_) capacity_ = std::max<GLsizeiptr>(bytes + bytes / 2, 1 << 16);
  glNamedBufferData(vbo_.id(), capacity_, nullptr, GL_STREAM_DRAW);
  glNamedBufferSubData(vbo_.id(), 0, bytes, vertices.data());
  gl::count_upload(std::uint64_t(bytes));

  const auto& hf = scene.heightfield();
  const glm::dvec2 spacing(hf.spacing_x_m, hf.spacing_y_m);
  const glm::ivec2 eye_sample(int(std::floor(camera.position.x / spacing.x)),
                              int(std::floor(camera.position.y / spacing.y)));
  program_.use();
  scene.bind_common(program_, camera);
  program_.set("u_eye_sample", eye_sample);
  program_.set("u_eye_frac", glm::vec3(camera.position.x - eye_sample.x * spacing.x,
                                       camera.position.y - eye_sample.y * spacing.y, camera.position.z));
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(vertices.size()));
  gl::count_draw();
}

MethodFrameStats SampleTriangleStream::draw_frame(const std::vector<glm::u16vec2>& vertices, const TerrainScene& scene,
                                                 const Camera& camera, long long triangles,
                                                 std::vector<std::pair<std::string, double>> columns) {
  draw(vertices, scene, camera);
  MethodFrameStats stats;
  stats.triangles = triangles;
  stats.passes = triangles > 0 ? "terrain" : "";
  stats.columns = std::move(columns);
  return stats;
}

}  // namespace ig::render
