#include "render/sample_triangle_stream.h"

#include <cmath>

namespace ig::render {

SampleTriangleStream::SampleTriangleStream(const TerrainScene& scene, const std::string& shader_dir)
    : program_(shader_dir, "level0.vert", scene.shading_stages({"terrain.frag"})) {}

void SampleTriangleStream::draw(const std::vector<glm::u16vec2>& vertices, const TerrainScene& scene,
                                const Camera& camera) {
  if (vertices.empty()) return;
  const auto& hf = scene.heightfield();
  const glm::dvec2 spacing(hf.spacing_x_m, hf.spacing_y_m);
  const glm::ivec2 eye_sample(int(std::floor(camera.position.x / spacing.x)),
                              int(std::floor(camera.position.y / spacing.y)));
  program_.use();
  scene.bind_common(program_, camera);
  program_.set("u_eye_sample", eye_sample);
  program_.set("u_eye_frac", glm::vec3(camera.position.x - eye_sample.x * spacing.x,
                                       camera.position.y - eye_sample.y * spacing.y, camera.position.z));
  stream_.draw(vertices);
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
