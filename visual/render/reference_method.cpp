#include "render/reference_method.h"

#include <algorithm>

#include "gl/uniform.h"

namespace ig::render {

ReferenceMethod::ReferenceMethod(const TerrainScene& scene, const std::string& shader_dir, int n)
    : scene_(scene), program_(shader_dir, "terrain_grid.vert", scene.shading_stages({"terrain.frag"})), mesh_(n) {
  const auto& hf = scene.heightfield();
  for (int j0 = 0; j0 < hf.height - 1; j0 += n)
    for (int i0 = 0; i0 < hf.width - 1; i0 += n) {
      Chunk c{i0, j0, std::min(n, hf.width - 1 - i0), std::min(n, hf.height - 1 - j0), 0, 0};
      float lo = hf.at(i0, j0), hi = lo;
      for (int j = j0; j <= j0 + c.quads_y; ++j)
        for (int i = i0; i <= i0 + c.quads_x; ++i) {
          lo = std::min(lo, hf.at(i, j));
          hi = std::max(hi, hf.at(i, j));
        }
      c.min_h = lo;
      c.max_h = hi;
      chunks_.push_back(c);
    }
}

ReferenceMethod::Selection ReferenceMethod::select(const Camera& camera) const {
  const auto& hf = scene_.heightfield();
  const Frustum frustum = frustum_of(camera);
  Selection sel;
  for (int k = 0; k < int(chunks_.size()); ++k) {
    const Chunk& c = chunks_[k];
    const glm::dvec3 lo(c.i0 * hf.spacing_x_m, c.j0 * hf.spacing_y_m, c.min_h);
    const glm::dvec3 hi((c.i0 + c.quads_x) * hf.spacing_x_m, (c.j0 + c.quads_y) * hf.spacing_y_m, c.max_h);
    if (frustum.intersects_box(lo - camera.position, hi - camera.position)) sel.visible.push_back(k);
  }
  return sel;
}

lod::SceneRequests ReferenceMethod::update(const Camera& camera) {
  selection_ = select(camera);
  return {};
}

MethodFrameStats ReferenceMethod::draw(const Camera& camera, const gl::RenderTarget&) {
  const auto& hf = scene_.heightfield();
  const std::vector<int>& visible = selection_.visible;
  MethodFrameStats stats;
  stats.passes = visible.empty() ? "" : "terrain";
  if (!visible.empty()) {
    program_.use();
    scene_.bind_common(program_, camera);
    const gl::Uniform origin(program_, "u_origin"), origin_rel(program_, "u_origin_rel");
    for (int k : visible) {
      const Chunk& c = chunks_[k];
      // Eye-relative chunk origin in double, then to float: no precision loss far from the origin.
      const glm::dvec3 rel = glm::dvec3(c.i0 * hf.spacing_x_m, c.j0 * hf.spacing_y_m, 0.0) - camera.position;
      origin.set(glm::ivec2(c.i0, c.j0));
      origin_rel.set(glm::vec3(rel));
      mesh_.draw();
      stats.triangles += 2LL * c.quads_x * c.quads_y;
    }
  }
  stats.columns = {{"chunks_drawn", double(visible.size())}, {"chunks_total", double(chunks_.size())}};
  return stats;
}

}  // namespace ig::render
