#pragma once
// Baseline "quadtree": the restricted quadtree LOD of the seed articles
// (002/003, after Röttger et al. 1998), rebuilt every frame: a node splits
// when f = L / (d * C1 * max(C2 * DHmax, 1)) < 1, adjacent leaves differ by
// at most one level, leaves are triangle fans with the midpoints toward
// coarser neighbours dropped (lod/quadtree_tessellator.h,
// docs/baselines.md). Drawn with level0.vert and the shared shading.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lod/quadtree_tessellator.h"
#include "render/triangle_list_method.h"

namespace ig::render {

using options::QuadtreeOptions;  // options/method_options.h

class QuadtreeMethod final : public TriangleListMethod {
 public:
  // Throws std::invalid_argument unless C1 > 0 and C2 >= 0 (finite).
  QuadtreeMethod(const TerrainScene& scene, const std::string& shader_dir, QuadtreeOptions options = {});
  std::string name() const override { return "quadtree"; }
  std::vector<std::string> column_names() const override;
  std::optional<ErrorKnob> knob() const override { return ErrorKnob{"C1", "", options_.c1}; }

  const lod::QuadtreeTessellator& tessellator() const { return tess_; }
  const lod::QuadtreeSelection& selection() const { return selection_; }

 private:
  std::vector<glm::u16vec2>& tessellate(const Camera& camera, const lod::BoxInView& in_view) override;
  double max_error_ratio() const override { return selection_.stats.max_error_ratio; }
  std::vector<std::pair<std::string, double>> frame_columns() const override;

  QuadtreeOptions options_;
  lod::QuadtreeTessellator tess_;
  lod::QuadtreeSelection selection_;  // update() -> draw()
};

}  // namespace ig::render
