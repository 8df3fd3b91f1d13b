#include "render/geomipmap_method.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <stdexcept>

#include "lod/chunk_quadtree.h"
#include "gl/work_counters.h"

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

GeoMipMapMethod::GeoMipMapMethod(const TerrainScene& scene, const std::string& shader_dir, double tau_px)
    : scene_(scene),
      tau_px_(tau_px),
      program_(shader_dir, "terrain_grid.vert", scene.shading_stages({"terrain.frag"})),
      blocks_(scene.heightfield()) {
  if (!(tau_px > 0.0) || !std::isfinite(tau_px))
    throw std::invalid_argument("geomipmap: tau_px must be a positive number of pixels, got " + std::to_string(tau_px));
  std::vector<std::int16_t> verts;
  for (int j = 0; j <= N; ++j)
    for (int i = 0; i <= N; ++i) verts.insert(verts.end(), {std::int16_t(i), std::int16_t(j)});
  vbo_ = gl::create_buffer(verts);
  vao_ = gl::create_vertex_array();
  glVertexArrayVertexBuffer(vao_.id(), 0, vbo_.id(), 0, 2 * sizeof(std::int16_t));
  gl::vertex_attrib_int(vao_, 0, 2, GL_SHORT, 0, 0);
  levels_.assign(blocks_.blocks().size(), 0);
  distances_.assign(blocks_.blocks().size(), 0.0);
}

std::vector<std::string> GeoMipMapMethod::column_names() const {
  return {"blocks_drawn", "blocks_stitched", "level_min", "level_max", "level_mean"};
}

void GeoMipMapMethod::set_viewport(int, int height_px) {
  if (height_px > 0) viewport_h_ = height_px;
}

void GeoMipMapMethod::update(const Camera& camera) {
  const auto& hf = scene_.heightfield();
  const double ppr = pixels_per_radian(camera, viewport_h_);
  // Every block's level first (culled ones too): a visible block's stitching
  // depends on its neighbours' levels.
  const auto& blocks = blocks_.blocks();
  for (size_t k = 0; k < blocks.size(); ++k) {
    glm::dvec3 lo, hi;
    block_box(hf, blocks[k], lo, hi);
    distances_[k] = lod::box_distance(camera.position, lo, hi);
    levels_[k] = lod::geomipmap_select_level(blocks[k].error, distances_[k], camera.near_m, ppr, tau_px_);
  }
  const Frustum frustum = frustum_of(camera);
  drawn_.clear();
  for (int by = 0; by < blocks_.blocks_y(); ++by)
    for (int bx = 0; bx < blocks_.blocks_x(); ++bx) {
      const size_t k = size_t(by) * blocks_.blocks_x() + bx;
      glm::dvec3 lo, hi;
      block_box(hf, blocks[k], lo, hi);
      if (!frustum.intersects_box(lo - camera.position, hi - camera.position)) continue;
      DrawnBlock d;
      d.bx = bx;
      d.by = by;
      d.config = blocks_.config_of(bx, by, levels_);
      d.distance_m = distances_[k];
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
      drawn_.push_back(d);
    }
}

const GeoMipMapMethod::Indices& GeoMipMapMethod::indices_for(const lod::GeoMipConfig& config) {
  auto it = indices_.find(config.key());
  if (it != indices_.end()) return it->second;
  std::vector<std::uint16_t> idx;
  for (const glm::ivec2& c : lod::geomipmap_triangles(config)) idx.push_back(std::uint16_t(c.y * (N + 1) + c.x));
  Indices ix;
  ix.count = GLsizei(idx.size());
  ix.ibo = gl::create_buffer(idx);
  return indices_.emplace(config.key(), std::move(ix)).first->second;
}

MethodFrameStats GeoMipMapMethod::draw(const Camera& camera, const gl::RenderTarget&) {
  const auto& hf = scene_.heightfield();
  MethodFrameStats stats;
  int stitched = 0, lmin = lod::kGeoMipLevels, lmax = 0;
  double lsum = 0.0;
  if (!drawn_.empty()) {
    stats.passes = "terrain";
    program_.use();
    scene_.bind_common(program_, camera);
    const GLint loc_origin = program_.location("u_origin");
    const GLint loc_rel = program_.location("u_origin_rel");
    glBindVertexArray(vao_.id());
    for (const DrawnBlock& d : drawn_) {
      const lod::GeoMipBlock& b = blocks_.block(d.bx, d.by);
      const Indices& ix = indices_for(d.config);
      glVertexArrayElementBuffer(vao_.id(), ix.ibo.id());
      // Eye-relative block origin in double, then to float (camera-relative rendering).
      const glm::dvec3 rel = glm::dvec3(b.i0 * hf.spacing_x_m, b.j0 * hf.spacing_y_m, 0.0) - camera.position;
      glProgramUniform2i(program_.id(), loc_origin, b.i0, b.j0);
      glProgramUniform3f(program_.id(), loc_rel, float(rel.x), float(rel.y), float(rel.z));
      glDrawElements(GL_TRIANGLES, ix.count, GL_UNSIGNED_SHORT, nullptr);
      gl::count_draw();
      stats.triangles += d.triangles;
      stitched += d.config.stitched();
      lmin = std::min(lmin, d.config.level);
      lmax = std::max(lmax, d.config.level);
      lsum += d.config.level;
    }
  }
  const double n = double(drawn_.size());
  stats.columns = {{"blocks_drawn", n},
                   {"blocks_stitched", double(stitched)},
                   {"level_min", drawn_.empty() ? 0.0 : double(lmin)},
                   {"level_max", double(lmax)},
                   {"level_mean", drawn_.empty() ? 0.0 : lsum / n}};
  return stats;
}

std::optional<double> GeoMipMapMethod::error_bound_px(const Camera& camera, int viewport_height_px) const {
  double worst = 0.0;
  for (const DrawnBlock& d : drawn_) worst = std::max(worst, d.error_per_m);
  return worst * pixels_per_radian(camera, viewport_height_px);
}

}  // namespace ig::render
