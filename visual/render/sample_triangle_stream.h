#pragma once
// A triangle list of DEM sample indices rebuilt on the CPU every frame (the
// ROAM and quadtree baselines), drawn with shaders/level0.vert and the shared
// shading through a stream buffer (gl/stream_vertices.h).

#include <string>
#include <vector>

#include <glm/gtc/type_precision.hpp>

#include "gl/shader_program.h"
#include "gl/stream_vertices.h"
#include "render/camera.h"
#include "render/terrain_method.h"
#include "render/terrain_scene.h"

namespace ig::render {

class SampleTriangleStream {
 public:
  SampleTriangleStream(const TerrainScene& scene, const std::string& shader_dir);

  // Uploads 3 vertices per triangle and draws them into the bound target.
  void draw(const std::vector<glm::u16vec2>& vertices, const TerrainScene& scene, const Camera& camera);
  // draw(), then the frame's stats: `triangles` in one pass named "terrain"
  // (no pass when there are none) and the method's own log columns.
  MethodFrameStats draw_frame(const std::vector<glm::u16vec2>& vertices, const TerrainScene& scene,
                              const Camera& camera, long long triangles,
                              std::vector<std::pair<std::string, double>> columns);

 private:
  gl::ShaderProgram program_;
  gl::StreamVertices stream_;
};

}  // namespace ig::render
