#include "render/geomipmap_method.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "lod/chunk_quadtree.h"

namespace ig::render {

namespace {
constexpr int N = lod::kGeoMipBlockQuads;

void block_box(const terrain::Heightfield& hf, const lod::GeoMipBlock& b, glm::dvec3& lo, glm::dvec3& hi) {
  lo = glm::dvec3(b.i0 * hf.spacing_x_m, b.j0 * hf.spacing_y_m, b.heights.min_m);
  hi = glm::dvec3(std::min(b.i0 + N, hf.width - 1) * hf.spacing_x_m, std::min(b.j0 + N, hf.height - 1) * hf.spacing_y_m,
                  b.heights.max_m);
}
// The box of a side's strip: the row of quads (`depth` samples deep) along it.
void strip_box(const terrain::Heightfield& hf, const lod::GeoMipBlock& b, int side, int depth, glm::dvec3& lo,
               glm::dvec3& hi) {
  block_box(hf, b, lo, hi);
  const double dx = depth * hf.spacing_x_m, dy = depth * hf.spacing_y_m;
  switch (side) {
    case lod::kSouth: hi.y = std::min(hi.y, lo.y + dy); break;
    case lod::kEast: lo.x = std::max(lo.x, (b.i0 + N - depth) * hf.spacing_x_m); break;
    case lod::kNorth: lo.y = std::max(lo.y, (b.j0 + N - depth) * hf.spacing_y_m); break;
    default: hi.x = std::min(hi.x, lo.x + dx); break;
  }
  // A strip past the DEM's edge is folded onto it.
  lo.x = std::min(lo.x, hi.x);
  lo.y = std::min(lo.y, hi.y);
}

}  // namespace

GeoMipMapMethod::GeoMipMapMethod(const TerrainScene& scene, const std::string& shader_dir,
                                 options::GeoMipMapOptions options)
    : TauMethod("geomipmap", scene, shader_dir, "terrain_grid.vert", options.tau_px, options.horizon_culling),
      blocks_(scene.heightfield()) {
  std::vector<std::int16_t> verts;
  for (int j = 0; j <= N; ++j)
    for (int i = 0; i <= N; ++i) verts.insert(verts.end(), {std::int16_t(i), std::int16_t(j)});
  mesh_ = gl::StaticMesh(verts, 2, {{2, 0}});
  selection_.levels.assign(blocks_.blocks().size(), 0);
}

std::vector<std::string> GeoMipMapMethod::column_names() const {
  return {"blocks_drawn", "blocks_stitched", "level_min", "level_max", "level_mean", "hidden_boxes"};
}

lod::SceneRequests GeoMipMapMethod::update(const Camera& camera) {
  selection_ = select(camera);
  // After the levels: a visible block's stitching depends on its neighbours, hidden or not.
  const auto& hf = scene_.heightfield();
  const auto box_of = [&](const DrawnBlock& d) {
    lod::HorizonCulling::Box b;
    block_box(hf, blocks_.block(d.bx, d.by), b.lo, b.hi);
    return b;
  };
  // A block's triangles span at most its coarsest (side) stride.
  const auto span_of = [](const DrawnBlock& d) {
    int level = d.config.level;
    for (int side : d.config.side_level) level = std::max(level, side);
    return 1 << level;
  };
  remove_hidden(camera, selection_.drawn, box_of, span_of);
  return {};
}

GeoMipMapMethod::Selection GeoMipMapMethod::select(const Camera& camera) const {
  const auto& hf = scene_.heightfield();
  const double ppr = viewport_pixels_per_radian(camera);
  // Every block's level first (culled ones too): a visible block's stitching
  // depends on its neighbours' levels.
  const auto& blocks = blocks_.blocks();
  Selection sel;
  sel.levels.resize(blocks.size());
  std::vector<double> distances(blocks.size());  // eye to each block's box
  for (size_t k = 0; k < blocks.size(); ++k) {
    glm::dvec3 lo, hi;
    block_box(hf, blocks[k], lo, hi);
    distances[k] = lod::box_distance(camera.position, lo, hi);
    sel.levels[k] = lod::geomipmap_select_level(blocks[k].error, distances[k], camera.near_m, ppr, tau_px_);
  }
  const Frustum frustum = frustum_of(camera);
  for (int by = 0; by < blocks_.blocks_y(); ++by)
    for (int bx = 0; bx < blocks_.blocks_x(); ++bx) {
      const size_t k = size_t(by) * blocks_.blocks_x() + bx;
      glm::dvec3 lo, hi;
      block_box(hf, blocks[k], lo, hi);
      if (!frustum.intersects_box(lo - camera.position, hi - camera.position)) continue;
      DrawnBlock d;
      d.bx = bx;
      d.by = by;
      d.config = blocks_.config_of(bx, by, sel.levels);
      d.distance_m = distances[k];
      const auto s = blocks_.stats(bx, by, d.config);
      d.error_m = s.error_m;
      d.triangles = s.triangles;
      d.error_per_m = blocks[k].error[size_t(d.config.level)] / std::max(d.distance_m, camera.near_m);
      for (int side = 0; side < 4; ++side) {
        const float e = blocks_.strip_error(bx, by, d.config, side);
        if (e <= 0.0f) continue;
        glm::dvec3 slo, shi;
        strip_box(hf, blocks[k], side, 1 << d.config.level, slo, shi);
        const double strip_distance = std::max(lod::box_distance(camera.position, slo, shi), camera.near_m);
        d.error_per_m = std::max(d.error_per_m, e / strip_distance);
      }
      sel.drawn.push_back(d);
    }
  // Nearest first, so the early depth test rejects what nearer blocks hide.
  std::stable_sort(sel.drawn.begin(), sel.drawn.end(),
                   [](const DrawnBlock& a, const DrawnBlock& b) { return a.distance_m < b.distance_m; });
  return sel;
}

int GeoMipMapMethod::indices_for(const lod::GeoMipConfig& config) {
  auto it = indices_.find(config.key());
  if (it != indices_.end()) return it->second;
  std::vector<std::uint16_t> idx;
  for (const glm::ivec2& c : lod::geomipmap_triangles(config)) idx.push_back(std::uint16_t(c.y * (N + 1) + c.x));
  return indices_.emplace(config.key(), mesh_.add_indices(idx)).first->second;
}

MethodFrameStats GeoMipMapMethod::draw(const Camera& camera, const gl::RenderTarget&) {
  const std::vector<DrawnBlock>& drawn = selection_.drawn;
  MethodFrameStats stats;
  int stitched = 0, lmin = lod::kGeoMipLevels, lmax = 0;
  double lsum = 0.0;
  if (!drawn.empty()) {
    stats.passes = "terrain";
    const Placement placement = begin_draw(camera);
    for (const DrawnBlock& d : drawn) {
      const lod::GeoMipBlock& b = blocks_.block(d.bx, d.by);
      const int indices = indices_for(d.config);
      place(placement, camera, b.i0, b.j0);
      mesh_.draw(indices);
      stats.triangles += d.triangles;
      stitched += d.config.stitched();
      lmin = std::min(lmin, d.config.level);
      lmax = std::max(lmax, d.config.level);
      lsum += d.config.level;
    }
  }
  const double n = double(drawn.size());
  stats.columns = {{"blocks_drawn", n},
                   {"blocks_stitched", double(stitched)},
                   {"level_min", drawn.empty() ? 0.0 : double(lmin)},
                   {"level_max", double(lmax)},
                   {"level_mean", drawn.empty() ? 0.0 : lsum / n},
                   {"hidden_boxes", double(hidden_boxes())}};
  return stats;
}

std::optional<double> GeoMipMapMethod::error_bound_px(const Camera& camera, int viewport_height_px) const {
  double worst = 0.0;
  for (const DrawnBlock& d : selection_.drawn) worst = std::max(worst, d.error_per_m);
  return worst * pixels_per_radian(camera, viewport_height_px);
}

}  // namespace ig::render
