#pragma once
// Baseline "quadtree": the restricted quadtree LOD of the seed articles
// (002/003, after Röttger et al. 1998), rebuilt every frame: a node splits
// when f = L / (d * C1 * max(C2 * DHmax, 1)) < 1, adjacent leaves differ by
// at most one level, leaves are triangle fans with the midpoints toward
// coarser neighbours dropped (lod/quadtree_tessellator.h,
// docs/baselines.md). Drawn with level0.vert and the shared shading.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lod/drawn_surface_occlusion.h"
#include "lod/quadtree_tessellator.h"
#include "render/sample_triangle_stream.h"
#include "render/terrain_method.h"

namespace ig::render {

using options::QuadtreeOptions;  // options/method_options.h

class QuadtreeMethod final : public TerrainMethod {
 public:
  // Throws std::invalid_argument unless C1 > 0 and C2 >= 0 (finite).
  QuadtreeMethod(const TerrainScene& scene, const std::string& shader_dir, QuadtreeOptions options = {});
  std::string name() const override { return "quadtree"; }
  std::vector<std::string> column_names() const override;
  lod::SceneRequests update(const Camera& camera) override;
  MethodFrameStats draw(const Camera& camera, const gl::RenderTarget& target) override;
  std::optional<ErrorKnob> knob() const override { return ErrorKnob{"C1", "", options_.c1}; }
  // Largest (fan error incl. dropped midpoints / distance to the leaf's box)
  // over the leaves of the last update, in pixels for this viewport.
  std::optional<double> error_bound_px(const Camera& camera, int viewport_height_px) const override;

  const lod::QuadtreeTessellator& tessellator() const { return tess_; }
  const lod::QuadtreeSelection& selection() const { return selection_; }
  double last_update_ms() const { return update_ms_; }

 private:
  const TerrainScene& scene_;
  QuadtreeOptions options_;
  lod::QuadtreeTessellator tess_;
  lod::QuadtreeSelection selection_;  // update() -> draw()
  std::unique_ptr<lod::DrawnSurfaceOcclusion> occlusion_;  // null: horizon culling off
  int hidden_boxes_ = 0;  // triangle groups hidden this frame
  SampleTriangleStream stream_;
  Frustum frustum_{};
  lod::BoxInView in_view_;
  double update_ms_ = 0.0;
};

}  // namespace ig::render
