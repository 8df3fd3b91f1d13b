#include "render/cdlod_method.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "gl/uniform.h"

namespace ig::render {

namespace {
constexpr int Q = lod::kChunkQuads;
constexpr int kMaxLods = 16;  // shaders/cdlod.vert's uniform arrays
}  // namespace

CdlodMethod::CdlodMethod(const TerrainScene& scene, const std::string& shader_dir, options::CdlodOptions options)
    : scene_(scene),
      lod0_range_(options.lod0_range),
      program_(shader_dir, "cdlod.vert", scene.shading_stages({"terrain.frag"})),
      tree_(scene.heightfield()),
      mesh_(Q) {
  if (!(lod0_range_ > 0.0) || !std::isfinite(lod0_range_))
    throw std::invalid_argument("cdlod: lod0_range must be a positive number of samples, got " +
                                std::to_string(lod0_range_));
  if (tree_.depth() >= kMaxLods)
    throw std::invalid_argument("cdlod: the DEM needs " + std::to_string(tree_.depth() + 1) + " LODs, at most " +
                                std::to_string(kMaxLods) + " are supported");
  const auto& hf = scene.heightfield();
  ranges_.lod0_range_m = lod0_range_ * std::sqrt(hf.spacing_x_m * hf.spacing_y_m);
  ranges_.top_lod = tree_.depth();

  for (const lod::ChunkNode& n : tree_.nodes()) {
    std::array<int, 4> t{};
    for (int q = 0; q < 4; ++q)
      t[q] = lod::grid_triangle_count(hf, n.i0 + (q & 1) * n.size() / 2, n.j0 + (q >> 1) * n.size() / 2, Q / 2,
                                      n.stride);
    quadrant_triangles_.push_back(t);
  }
  if (options.horizon_culling) occlusion_ = std::make_unique<lod::DrawnSurfaceOcclusion>(hf, scene.height_pyramid());
}

std::vector<std::string> CdlodMethod::column_names() const {
  return {"nodes_drawn", "quarters_drawn", "lod_min", "lod_max", "hidden_boxes"};
}

lod::SceneRequests CdlodMethod::update(const Camera& camera) {
  areas_ = select(camera);
  // Nearest node first, so the early depth test rejects what nearer areas hide.
  std::vector<std::pair<double, lod::CdlodArea>> by_distance;
  by_distance.reserve(areas_.size());
  for (const lod::CdlodArea& a : areas_) {
    glm::dvec3 lo, hi;
    tree_.box(tree_.node(a.node), lo, hi);
    by_distance.emplace_back(lod::box_distance(camera.position, lo, hi), a);
  }
  std::stable_sort(by_distance.begin(), by_distance.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (size_t k = 0; k < areas_.size(); ++k) areas_[k] = by_distance[k].second;
  hidden_boxes_ = 0;
  if (!occlusion_) return {};
  const auto box_of = [&](const lod::CdlodArea& a) {
    lod::HorizonCulling::Box b;
    const lod::ChunkNode& n = tree_.node(a.node);
    if (a.quadrant < 0)
      tree_.box(n, b.lo, b.hi);
    else
      tree_.quadrant_box(n, a.quadrant, b.lo, b.hi);
    return b;
  };
  // A node's triangles, morphing towards its parent's grid, span at most
  // two quads of its stride.
  const auto span_of = [&](const lod::CdlodArea& a) { return 2 * tree_.node(a.node).stride; };
  hidden_boxes_ = occlusion_->remove_hidden(camera.position, camera.earth_radius_m, 10.0 * camera.near_m, areas_,
                                            box_of, span_of);
  return {};
}

std::vector<lod::CdlodArea> CdlodMethod::select(const Camera& camera) const {
  const Frustum frustum = frustum_of(camera);
  return lod::cdlod_select(tree_, ranges_, camera.position, [&](const glm::dvec3& lo, const glm::dvec3& hi) {
    return frustum.intersects_box(lo - camera.position, hi - camera.position);
  });
}

MethodFrameStats CdlodMethod::draw(const Camera& camera, const gl::RenderTarget&) {
  const auto& hf = scene_.heightfield();
  MethodFrameStats stats;
  int quarters = 0, lmin = ranges_.top_lod, lmax = 0;
  if (!areas_.empty()) {
    stats.passes = "terrain";
    program_.use();
    scene_.bind_common(program_, camera);
    std::array<float, kMaxLods> start{}, end{};
    for (int l = 0; l < ranges_.top_lod; ++l) {
      start[size_t(l)] = float(ranges_.morph_start(l));
      end[size_t(l)] = float(ranges_.morph_end(l));
    }
    gl::Uniform(program_, "u_morph_start").set(start.data(), kMaxLods);
    gl::Uniform(program_, "u_morph_end").set(end.data(), kMaxLods);
    program_.set("u_top_lod", ranges_.top_lod);
    // The eye as a whole sample plus the rest (in double, then float).
    const glm::ivec2 eye_sample(int(std::floor(camera.position.x / hf.spacing_x_m)),
                                int(std::floor(camera.position.y / hf.spacing_y_m)));
    program_.set("u_eye_sample", eye_sample);
    program_.set("u_eye_frac", glm::vec3(float(camera.position.x - eye_sample.x * hf.spacing_x_m),
                                         float(camera.position.y - eye_sample.y * hf.spacing_y_m),
                                         float(camera.position.z)));
    const gl::Uniform origin(program_, "u_origin"), node_lod(program_, "u_lod");
    for (const lod::CdlodArea& a : areas_) {
      const lod::ChunkNode& n = tree_.node(a.node);
      origin.set(glm::ivec2(n.i0, n.j0));
      node_lod.set(a.lod);
      if (a.quadrant < 0) {
        mesh_.draw();
        stats.triangles += n.triangles;
      } else {
        mesh_.draw_quadrant(a.quadrant);
        stats.triangles += quadrant_triangles_[size_t(a.node)][size_t(a.quadrant)];
        ++quarters;
      }
      lmin = std::min(lmin, a.lod);
      lmax = std::max(lmax, a.lod);
    }
  }
  stats.columns = {{"nodes_drawn", double(areas_.size() - size_t(quarters))},
                   {"quarters_drawn", double(quarters)},
                   {"lod_min", areas_.empty() ? 0.0 : double(lmin)},
                   {"lod_max", double(lmax)},
                   {"hidden_boxes", double(hidden_boxes_)}};
  return stats;
}

std::optional<double> CdlodMethod::error_bound_px(const Camera& camera, int viewport_height_px) const {
  double worst = 0.0;  // metres per metre of distance
  for (const lod::CdlodArea& a : areas_) {
    const lod::ChunkNode& n = tree_.node(a.node);
    glm::dvec3 lo, hi;
    if (a.quadrant < 0) {
      tree_.box(n, lo, hi);
    } else {
      tree_.quadrant_box(n, a.quadrant, lo, hi);
    }
    const double near_d = std::max(lod::box_distance(camera.position, lo, hi), camera.near_m);
    const double far_d = std::max(lod::box_far_distance(camera.position, lo, hi), near_d);
    // Walk up the LODs the piece's points show: LOD l from max(near, where
    // l-1's morph ends) on; in [morph_start(l), morph_end(l)) it blends l and l+1.
    int anc = a.node;
    for (int l = a.lod;; ++l) {
      const lod::ChunkNode& node_l = tree_.node(anc);
      const double from = l == a.lod ? near_d : std::max(near_d, ranges_.morph_end(l - 1));
      if (from > far_d) break;
      const double ms = ranges_.morph_start(l);
      if (from < ms) worst = std::max(worst, node_l.own_error_m / from);
      if (l >= ranges_.top_lod || node_l.parent < 0) break;
      if (far_d >= ms) {
        const double e = std::max(node_l.own_error_m, tree_.node(node_l.parent).own_error_m);
        worst = std::max(worst, e / std::max(from, ms));
      }
      if (far_d < ranges_.morph_end(l)) break;
      anc = node_l.parent;
    }
  }
  return worst * pixels_per_radian(camera, viewport_height_px);
}

}  // namespace ig::render
