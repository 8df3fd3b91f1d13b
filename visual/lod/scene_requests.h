#pragma once
// What one frame's selection asks of the terrain scene, as a value: tiles to
// prefetch and where a height window goes. The selection (no GL) only says
// what it needs; the scene step (render::TerrainScene::apply) carries it out
// between update and draw, so uploads and paging requests have one place.

#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ig::lod {

struct SceneRequests {
  // Applied in this order: the points' and rectangles' tiles (around points in
  // terrain-local metres; sample rectangles inclusive), the window, then the
  // tiles of square_and_band (its samples and the ring the window read next).
  std::vector<glm::dvec3> points_m;
  std::vector<std::pair<glm::ivec2, glm::ivec2>> sample_rects;
  int window_set = -1;  // the scene's window set to centre on window_centre (-1: none)
  glm::ivec2 window_centre{0};
  std::pair<glm::ivec2, glm::ivec2> square_and_band{glm::ivec2(0), glm::ivec2(-1)};  // empty: lo > hi

  bool empty() const {
    return points_m.empty() && sample_rects.empty() && window_set < 0 &&
           (square_and_band.first.x > square_and_band.second.x || square_and_band.first.y > square_and_band.second.y);
  }
};

}  // namespace ig::lod
