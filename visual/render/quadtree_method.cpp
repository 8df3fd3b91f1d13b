#include "render/quadtree_method.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace ig::render {

QuadtreeMethod::QuadtreeMethod(const TerrainScene& scene, const std::string& shader_dir, QuadtreeOptions options)
    : TriangleListMethod(scene, shader_dir, options.horizon_culling), options_(options), tess_(scene.heightfield()) {
  if (!(options_.c1 > 0.0) || !std::isfinite(options_.c1) || !(options_.c2 >= 0.0) || !std::isfinite(options_.c2))
    throw std::invalid_argument("quadtree: C1 must be > 0 and C2 >= 0, both finite (got C1 = " +
                                std::to_string(options_.c1) + ", C2 = " + std::to_string(options_.c2) + ")");
}

std::vector<std::string> QuadtreeMethod::column_names() const {
  return {"nodes_evaluated", "splits", "forced_splits", "leaves", "culled_leaves", "hidden_boxes"};
}

std::vector<glm::u16vec2>& QuadtreeMethod::tessellate(const Camera& camera, const lod::BoxInView& in_view) {
  selection_ = tess_.select(camera.position, options_.c1, options_.c2, in_view, std::max(camera.near_m, 1e-3),
                            std::move(selection_));
  return selection_.vertices;
}

std::vector<std::pair<std::string, double>> QuadtreeMethod::frame_columns() const {
  const auto& s = selection_.stats;
  return {{"nodes_evaluated", double(s.evaluated)},
          {"splits", double(s.splits)},
          {"forced_splits", double(s.forced_splits)},
          {"leaves", double(s.leaves)},
          {"culled_leaves", double(s.culled)}};
}

}  // namespace ig::render
