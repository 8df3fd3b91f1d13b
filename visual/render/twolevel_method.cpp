#include "render/twolevel_method.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <utility>

#include "gl/gl_context.h"
#include "gl/scoped_disable.h"
#include "lod/level0_budget.h"
#include "lod/level0_envelope.h"
#include "lod/level1_coverage_predictor.h"
#include "lod/level1_selection.h"
#include "lod/terrain_floors.h"
#include "render/scene_level0.h"
#include "terrain/back_faces_hidden.h"
#include "terrain/height_tile_cache.h"

namespace ig::render {
namespace {

constexpr int kBlockQuads = lod::kLevel1BlockQuads;
// Occluder cells of 2^5 = 32 samples a side for horizon culling.
constexpr int kFloorCellLevel = 5;

// Whether any part of the terrain can be in view: the frustum against the
// min/max pyramid's boxes, descending to nodes of 64 cells. The single
// whole-DEM box is too coarse (it always straddles the planes through the eye).
bool terrain_in_view(const terrain::HeightPyramid& p, const terrain::Heightfield& hf, const Frustum& frustum,
                     const glm::dvec3& eye, int level, int i, int j) {
  const int size = 1 << level;
  const int i0 = i * size, j0 = j * size;
  const int i1 = std::min(i0 + size, p.cells_x()), j1 = std::min(j0 + size, p.cells_y());
  const auto mm = p.node(level, i, j);
  const glm::dvec3 lo(i0 * hf.spacing_x_m, j0 * hf.spacing_y_m, mm.lo), hi(i1 * hf.spacing_x_m, j1 * hf.spacing_y_m, mm.hi);
  if (!frustum.intersects_box(lo - eye, hi - eye)) return false;
  if (level == 0 || size <= 64) return true;
  for (int cj = 2 * j; cj <= 2 * j + 1 && cj < p.level_height(level - 1); ++cj)
    for (int ci = 2 * i; ci <= 2 * i + 1 && ci < p.level_width(level - 1); ++ci)
      if (terrain_in_view(p, hf, frustum, eye, level - 1, ci, cj)) return true;
  return false;
}

}  // namespace

// Walls around Level1's square (close the step between Level1's edge and
// Level0's coarser surface there, whichever is higher) and the transition
// band ring, for one (N, w_trans) pair.
struct TwoLevelMethod::SizeMeshes {
  gl::VertexArray wall_vao;
  gl::Buffer wall_local, wall_heights, wall_ibo;
  GLsizei wall_indices = 0;
  std::vector<glm::ivec2> perimeter;  // Level1 edge samples, relative to its origin
  std::vector<glm::vec2> wall_z;      // per wall vertex: (1, absolute height)
  gl::VertexArray ring_vao;
  gl::Buffer ring_vbo, ring_ibo;
  GLsizei ring_indices = 0;

  SizeMeshes(int n, int w, int stride) {
    // Walls: the square's perimeter twice (top and bottom vertex per edge sample).
    for (int i = 0; i < n - 1; ++i) perimeter.push_back({i, 0});
    for (int j = 0; j < n - 1; ++j) perimeter.push_back({n - 1, j});
    for (int i = n - 1; i > 0; --i) perimeter.push_back({i, n - 1});
    for (int j = n - 1; j > 0; --j) perimeter.push_back({0, j});
    std::vector<std::int16_t> local;
    for (const auto& p : perimeter)
      for (int k = 0; k < 2; ++k) local.insert(local.end(), {std::int16_t(p.x), std::int16_t(p.y)});
    wall_z.assign(perimeter.size() * 2, glm::vec2(0.0f));
    std::vector<std::uint32_t> idx;
    const auto m = std::uint32_t(perimeter.size());
    for (std::uint32_t k = 0; k < m; ++k) {
      const std::uint32_t a = 2 * k, b = 2 * ((k + 1) % m);
      idx.insert(idx.end(), {a, b, b + 1, a, b + 1, a + 1});
    }
    wall_indices = GLsizei(idx.size());
    wall_local = gl::create_buffer(local);
    wall_heights = gl::create_buffer(wall_z, GL_DYNAMIC_STORAGE_BIT);
    wall_ibo = gl::create_buffer(idx);
    wall_vao = gl::create_vertex_array();
    glVertexArrayVertexBuffer(wall_vao.id(), 0, wall_local.id(), 0, 4);
    glVertexArrayVertexBuffer(wall_vao.id(), 1, wall_heights.id(), 0, sizeof(glm::vec2));
    glVertexArrayElementBuffer(wall_vao.id(), wall_ibo.id());
    gl::vertex_attrib_int(wall_vao, 0, 2, GL_SHORT, 0, 0);
    gl::vertex_attrib_float(wall_vao, 1, 2, GL_FLOAT, 0, 1);

    // Band ring: the grid grown by w on every side, minus Level1's square,
    // every `stride` samples (w and n - 1 are multiples of stride).
    local.clear();
    idx.clear();
    const int side = (n - 1 + 2 * w) / stride + 1;
    for (int b = 0; b < side; ++b)
      for (int a = 0; a < side; ++a) {
        local.push_back(std::int16_t(-w + a * stride));
        local.push_back(std::int16_t(-w + b * stride));
      }
    auto v = [side](int a, int b) { return std::uint32_t(b * side + a); };
    for (int b = 0; b + 1 < side; ++b)
      for (int a = 0; a + 1 < side; ++a) {
        const int x = -w + a * stride, y = -w + b * stride;
        const bool inside = x >= 0 && y >= 0 && x + stride <= n - 1 && y + stride <= n - 1;
        if (inside) continue;
        idx.insert(idx.end(), {v(a, b), v(a + 1, b), v(a + 1, b + 1), v(a, b), v(a + 1, b + 1), v(a, b + 1)});
      }
    ring_indices = GLsizei(idx.size());
    ring_vbo = gl::create_buffer(local);
    ring_ibo = gl::create_buffer(idx);
    ring_vao = gl::create_vertex_array();
    glVertexArrayVertexBuffer(ring_vao.id(), 0, ring_vbo.id(), 0, 4);
    glVertexArrayElementBuffer(ring_vao.id(), ring_ibo.id());
    gl::vertex_attrib_int(ring_vao, 0, 2, GL_SHORT, 0, 0);
  }
};

namespace {
// "auto" (0) without a display to derive it from: the reference display's budget.
TwoLevelOptions with_budget(TwoLevelOptions o) {
  if (o.level0_budget == 0) o.level0_budget = lod::level0_budget_for_display(0.0);
  return o;
}
}  // namespace

TwoLevelMethod::TwoLevelMethod(const TerrainScene& scene, const std::string& shader_dir, TwoLevelOptions options)
    : scene_(scene),
      options_(with_budget(std::move(options))),
      grid_program_(shader_dir, "terrain_grid.vert", scene.shading_stages({"terrain.frag"})),
      level0_program_(shader_dir, "level0.vert", scene.shading_stages({"level0_blend.frag", "level0.frag"})),
      level0_clipped_program_(shader_dir, "level0.vert",
                              scene.shading_stages({"level0_blend.frag", "level0_clipped.frag"})),
      band_program_(shader_dir, "terrain_grid.vert", "band.frag"),
      shader_dir_(shader_dir),
      pyramid_(scene.height_pyramid()),
      level0_(lod::z_ordered(build_scene_level0(scene,  // on the overview beyond the texture limit
                                                lod::Level0Options{options_.level0_budget, 0.0, scene.earth_radius_m(),
                                                                   options_.level0_whole_error}))),
      level0_heights_(level0_, scene.heightfield().width, scene.heightfield().height),
      block_mesh_(kBlockQuads),
      controller_(lod::level1_ladder(scene.heightfield().width, scene.heightfield().height, options.max_level1),
                  lod::SizeControllerOptions{options.a1, options.a2}) {
  const auto& hf = scene.heightfield();
  level0_resolution_ = double(level0_.samples.size()) / (double(hf.width) * hf.height);

  std::vector<float> lift(level0_.samples.size(), 0.0f);
  if (options_.level0_envelope) {
    lift = lod::level0_upper_envelope(level0_, hf, scene.earth_radius_m()).lift_m;
    for (size_t v = 0; v < lift.size(); ++v) level0_.positions[v].z += lift[v];  // the walls' height query
  }
  // Per vertex: sample index (2 x i32) and lift (f32).
  std::vector<std::int32_t> samples;
  level0_clusters_ = std::make_unique<lod::Level0Clusters>(level0_, glm::dvec2(hf.spacing_x_m, hf.spacing_y_m));
  if (options_.horizon_culling && !pyramid_.empty())
    horizon_ = std::make_unique<lod::HorizonCulling>(lod::terrain_floors(level0_, pyramid_, kFloorCellLevel),
                                                     glm::dvec2(hf.spacing_x_m, hf.spacing_y_m));
  for (size_t v = 0; v < level0_.samples.size(); ++v) {
    std::int32_t bits = 0;
    std::memcpy(&bits, &lift[v], 4);
    samples.insert(samples.end(), {level0_.samples[v].x, level0_.samples[v].y, bits});
  }
  level0_vbo_ = gl::create_buffer(samples);
  level0_ibo_ = gl::create_buffer(level0_.indices);
  level0_vao_ = gl::create_vertex_array();
  glVertexArrayVertexBuffer(level0_vao_.id(), 0, level0_vbo_.id(), 0, 12);
  glVertexArrayElementBuffer(level0_vao_.id(), level0_ibo_.id());
  gl::vertex_attrib_int(level0_vao_, 0, 2, GL_INT, 0, 0);
  gl::vertex_attrib_float(level0_vao_, 1, 1, GL_FLOAT, 8, 0);

  // The count pass draws into a framebuffer without attachments.
  count_fbo_ = gl::create_framebuffer();
  glNamedFramebufferParameteri(count_fbo_.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, 1);
  glNamedFramebufferParameteri(count_fbo_.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, 1);
  empty_vao_ = gl::create_vertex_array();
  for (auto& pair : queries_)
    for (auto& q : pair) q = gl::create_query();
  windows_ = scene.claim_windows();  // this channel's height (and imagery) window
}

TwoLevelMethod::~TwoLevelMethod() { scene_.release_windows(windows_); }

std::vector<std::string> TwoLevelMethod::pass_names() const {
  if (options_.band_inline) return {"level1", "level0", "count"};  // the band is shaded inside level0
  return {"level1", "band", "level0", "count"};
}

std::vector<std::string> TwoLevelMethod::column_names() const {
  return {"level1_n", "level1_ratio", "level0_tris", "level1_tris", "band_tris", "band_w", "e_x", "e_y", "e_hit",
          "level0_hidden_clusters", "level1_hidden_blocks", "level1_held", "level1_far"};
}

TwoLevelMethod::SizeMeshes& TwoLevelMethod::meshes_for(int n, int band_w) {
  auto& slot = size_meshes_[{n, band_w}];
  if (!slot) slot = std::make_unique<SizeMeshes>(n, band_w, std::min(options_.band_stride, std::max(band_w, 1)));
  return *slot;
}

double TwoLevelMethod::read_previous_ratio() {
  // Results of the frame before: never wait for them (no stall); if the
  // driver has not finished, keep the size one more frame.
  const int prev = parity_ ^ 1;
  if (!query_pending_[prev]) return -1.0;
  GLuint available = 0;
  glGetQueryObjectuiv(queries_[prev][1].id(), GL_QUERY_RESULT_AVAILABLE, &available);
  if (!available) return -1.0;
  GLuint64 level1 = 0, terrain = 0;
  glGetQueryObjectui64v(queries_[prev][0].id(), GL_QUERY_RESULT, &level1);
  glGetQueryObjectui64v(queries_[prev][1].id(), GL_QUERY_RESULT, &terrain);
  query_pending_[prev] = false;
  return terrain > 0 ? double(level1) / double(terrain) : -1.0;
}

bool TwoLevelMethod::place_level1(const Camera& camera, double ratio, const glm::dvec2& eye) {
  const auto& hf = scene_.heightfield();
  // Paged heights (issue 16), live (TerrainScene::wait_for_pages() false):
  // after the first frame nothing here waits on a tile. A read of one that
  // is not resident queues it and throws; a square whose heights (square,
  // band, height window) are not all in is refused. Either way Level1 keeps
  // last frame's square until they are.
  std::optional<terrain::HeightTileCache::NoWait> no_wait;
  if (hf.paged && n_ > 0 && !scene_.wait_for_pages()) no_wait.emplace();
  try {
    const lod::LookAtPoint e = lod::find_look_at_point(hf, pyramid_, camera.position, camera.forward(), camera.up(),
                                                       camera.earth_radius_m);
    // Snap E to a whole sample and keep the square inside the DEM.
    const glm::ivec2 ec{int(std::lround(e.point.x / hf.spacing_x_m)), int(std::lround(e.point.y / hf.spacing_y_m))};
    const double eye_agl =
        options_.eye_guard ? camera.position.z - hf.sample_bilinear(camera.position.x, camera.position.y) : 0.0;
    int n = 0;
    // Level1 is worth its vertices only where Level0's error would show. When
    // even the largest square around E reaches no terrain nearer than where
    // Level0's largest error is under kFarLevel0ErrorPx (E far out: a range
    // beyond a ridge, the horizon), Level1 takes the smallest size and the
    // size controller waits (before, a far E grew Level1 to its largest,
    // 10^6 vertices for a few pixels).
    const double reach = 0.5 * std::sqrt(2.0) * (controller_.ladder().back() - 1) *
                         std::max(hf.spacing_x_m, hf.spacing_y_m);  // E to the corners of the largest square
    const double nearest = glm::length(e.point - camera.position) - reach;
    const bool far = nearest > 0.0 && level0_.max_error_m * pixels_per_radian(camera, viewport_.y) < kFarLevel0ErrorPx * nearest;
    if (far) {
      n = controller_.ladder().front();
    } else if (options_.predict_size && terrain_visible_) {
      // R for every ladder size on a 12 x 9 grid of view rays (about 0.1-0.3 ms).
      constexpr int kRaysX = 12, kRaysY = 9;
      prediction_rays_.clear();
      for (int y = 0; y < kRaysY; ++y)
        for (int x = 0; x < kRaysX; ++x)
          prediction_rays_.push_back(camera.pixel_ray((x + 0.5) * viewport_.x / kRaysX,
                                                      (y + 0.5) * viewport_.y / kRaysY, viewport_.x, viewport_.y));
      auto p = lod::predict_level1_coverage(hf, pyramid_, camera.position, prediction_rays_, camera.far_m, ec,
                                            controller_.ladder());
      scene_.prefetch_heights(p.hits);  // paged heights: keep the tiles under the view resident
      n = controller_.update(ratio, p.ratio);
    } else {
      n = controller_.update(ratio);
    }
    // Far out, the small square goes under the eye instead (over the DEM),
    // so the eye guard need not grow it to the largest to reach from E.
    const bool eye_on_dem = eye.x >= 0 && eye.y >= 0 && eye.x <= hf.width - 1 && eye.y <= hf.height - 1;
    lod::Level1Placement place{n, far && eye_on_dem ? glm::ivec2(glm::round(eye)) : ec, false};
    if (options_.eye_guard)
      place = lod::guard_level1_for_eye(place, eye, eye_agl, level0_.max_error_m, controller_.ladder(),
                                        {hf.width, hf.height});
    const glm::ivec2 origin = lod::level1_square_origin(place.centre, place.n, hf.width, hf.height);
    if (no_wait) {
      const int band = lod::band_width_samples(level0_resolution_, options_.alpha, place.n, options_.band_stride);
      const glm::ivec2 lo = origin - band, hi = origin + (place.n - 1) + band;
      scene_.prefetch_samples(lo, hi);
      if (!scene_.samples_resident(lo, hi) || !scene_.window_ready(windows_, origin + (place.n - 1) / 2)) return false;
    }
    look_at_ = e;
    far_ = far;
    eye_guarded_ = place.eye_guarded;
    n_ = place.n;
    origin_ = origin;
    return true;
  } catch (const terrain::TileNotResident&) {
    return false;
  }
}

void TwoLevelMethod::update(const Camera& camera) {
  const auto& hf = scene_.heightfield();
  const Frustum frustum = frustum_of(camera);
  terrain_visible_ = !pyramid_.empty() &&
                     terrain_in_view(pyramid_, hf, frustum, camera.position, pyramid_.num_levels() - 1, 0, 0);

  const double ratio = read_previous_ratio();
  if (ratio >= 0.0) last_ratio_ = ratio;

  const glm::dvec2 eye(camera.position.x / hf.spacing_x_m, camera.position.y / hf.spacing_y_m);
  scene_.prefetch_samples(glm::ivec2(eye), glm::ivec2(eye));  // paged heights: the ground under the eye
  level1_held_ = !place_level1(camera, ratio, eye);
  scene_.follow_window(windows_, origin_ + (n_ - 1) / 2);  // the height window, if any, on Level1 (terrain_scene.h)
  const int n = n_;
  band_w_ = lod::band_width_samples(level0_resolution_, options_.alpha, n, options_.band_stride);

  // Paged heights: Level1's square and band (their bounds read the finest
  // pyramid levels along the edges) for the background thread.
  scene_.prefetch_samples(origin_ - band_w_, origin_ + (n - 1) + band_w_);
  visible_blocks_.clear();
  level0_hidden_clusters_ = level1_hidden_blocks_ = 0;
  if (!terrain_visible_) {
    band_visible_ = false;
    return;
  }
  // Blocks and clusters behind nearer terrain are not drawn either, while
  // the eye is above what is drawn under it (the DEM, and Level0 when
  // Level1 does not hold the eye): lod/horizon_culling.h.
  const bool eye_in_square = eye.x >= origin_.x && eye.y >= origin_.y && eye.x <= origin_.x + n - 1 &&
                             eye.y <= origin_.y + n - 1;
  bool eye_above = false;
  try {  // paged heights: no wait for the ground under the eye; not in yet, no culling this frame
    std::optional<terrain::HeightTileCache::NoWait> no_wait;
    if (hf.paged && !scene_.wait_for_pages()) no_wait.emplace();
    eye_above = terrain::back_faces_hidden(hf, camera.position) &&
                (eye_in_square || camera.position.z > level0_heights_.height_at(eye.x, eye.y));
  } catch (const terrain::TileNotResident&) {
  }
  int hidden_count = 0;
  lod::MarkHidden occlusion;
  if (horizon_ && eye_above)
    occlusion = [&](const std::vector<lod::HorizonCulling::Box>& boxes, std::vector<std::uint8_t>& hidden) {
      hidden_count = horizon_->mark_hidden(camera.position, camera.earth_radius_m, 10.0 * camera.near_m, boxes, hidden);
    };
  visible_blocks_ = lod::visible_level1_blocks(
      hf, pyramid_, origin_, n, level0_.max_error_m,
      [&](const glm::dvec3& lo, const glm::dvec3& hi) {
        return frustum.intersects_box(lo - camera.position, hi - camera.position);
      },
      eye, occlusion);
  level1_hidden_blocks_ = std::exchange(hidden_count, 0);
  const glm::ivec2 g0 = origin_ - band_w_, g1 = origin_ + (n - 1) + band_w_;
  const auto mm = lod::rect_minmax(pyramid_, g0.x, g0.y, g1.x, g1.y);
  const glm::dvec3 band_lo =
      glm::dvec3(std::max(g0.x, 0) * hf.spacing_x_m, std::max(g0.y, 0) * hf.spacing_y_m, mm.lo) - camera.position;
  const glm::dvec3 band_hi = glm::dvec3(std::min(g1.x, hf.width - 1) * hf.spacing_x_m,
                                        std::min(g1.y, hf.height - 1) * hf.spacing_y_m, mm.hi) - camera.position;
  band_visible_ = frustum.intersects_box(band_lo, band_hi);
  // The band target is cleared, drawn and read only inside the band's screen rectangle.
  if (!options_.band_inline) band_rect_ = screen_rect_of_box(camera, band_lo, band_hi, viewport_.x, viewport_.y);
  // The rest of the frame's CPU work, so it counts as LOD time: the seam
  // walls' heights (draw() uploads them) and which Level0 runs to draw.
  if (!visible_blocks_.empty()) update_walls(meshes_for(n, band_w_), n);
  // Level0: clusters of the static buffer outside the view are skipped whole;
  // inside the square nothing is drawn; outside it no discard, so the depth
  // test can reject hidden fragments early.
  level0_clusters_->select(origin_, origin_ + (n - 1),
                           [&](const glm::dvec3& lo, const glm::dvec3& hi) {
                             return frustum.intersects_box(lo - camera.position, hi - camera.position);
                           },
                           level0_runs_[0], level0_runs_[1], occlusion);
  level0_hidden_clusters_ = hidden_count;
  // As glMultiDrawElements takes them (counts, byte offsets into the index buffer).
  for (int k = 0; k < 2; ++k) {
    draw_counts_[k].assign(level0_runs_[k].count.begin(), level0_runs_[k].count.end());
    draw_offsets_[k].clear();
    for (auto first : level0_runs_[k].first)
      draw_offsets_[k].push_back(reinterpret_cast<const void*>(std::uintptr_t(first) * sizeof(std::uint32_t)));
  }
}

void TwoLevelMethod::ensure_band_target(int width, int height) {
  if (!band_target_ || band_target_->width() != width || band_target_->height() != height)
    band_target_ = std::make_unique<gl::RenderTarget>(width, height, GL_RGBA16F);
}

void TwoLevelMethod::upload_beta_template(int n, int band_w) {
  // The paper's 256 x 256 weight template over the grown square: 1 over
  // Level1, falling to 0 across the band (linear or Gaussian).
  if (beta_tex_ && beta_for_ == std::make_pair(n, band_w)) return;
  constexpr int kSize = 256;
  const double inner = 0.5 * (n - 1) / (0.5 * (n - 1) + band_w);  // Level1's half side / grown half side
  std::vector<float> beta(kSize * kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double qx = std::abs((x + 0.5) / kSize * 2.0 - 1.0), qy = std::abs((y + 0.5) / kSize * 2.0 - 1.0);
      const double t = std::clamp((std::max(qx, qy) - inner) / (1.0 - inner), 0.0, 1.0);
      const double g = std::exp(-4.5);
      beta[y * kSize + x] =
          float(options_.gaussian_beta ? (std::exp(-4.5 * t * t) - g) / (1.0 - g) : 1.0 - t);
    }
  if (!beta_tex_) {
    beta_tex_ = gl::create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(beta_tex_.id(), 1, GL_R16F, kSize, kSize);
    glTextureParameteri(beta_tex_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(beta_tex_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(beta_tex_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(beta_tex_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  glTextureSubImage2D(beta_tex_.id(), 0, 0, 0, kSize, kSize, GL_RED, GL_FLOAT, beta.data());
  gl::count_upload(std::uint64_t(beta.size() * sizeof(float)));
  beta_for_ = {n, band_w};
}

void TwoLevelMethod::update_walls(SizeMeshes& m, int n) {
  // Each wall spans from the higher of (Level1 edge, Level0 surface) down to
  // a little below the lower one, so no sliver opens where Level0's surface
  // bends between edge samples.
  constexpr float kBelow = 1.0f;
  const auto& hf = scene_.heightfield();
  for (size_t k = 0; k < m.perimeter.size(); ++k) {
    const glm::ivec2 s = origin_ + m.perimeter[k];
    const float h1 = hf.at_clamped(s.x, s.y);
    const double q = level0_heights_.height_at(s.x, s.y);
    const float h0 = std::isfinite(q) ? float(q) : h1;
    m.wall_z[2 * k] = {1.0f, std::max(h0, h1)};
    m.wall_z[2 * k + 1] = {1.0f, std::min(h0, h1) - kBelow};
  }
}

MethodFrameStats TwoLevelMethod::draw(const Camera& camera, const gl::RenderTarget& target) {
  const auto& hf = scene_.heightfield();
  const int n = n_;
  MethodFrameStats stats;
  long long level1_tris = 0, band_tris = 0, level0_tris = 0;
  std::vector<std::string> passes;
  auto rel = [&](glm::ivec2 s) {
    return glm::vec3(glm::dvec3(s.x * hf.spacing_x_m, s.y * hf.spacing_y_m, 0.0) - camera.position);
  };
  const glm::vec4 box(origin_.x, origin_.y, origin_.x + n - 1, origin_.y + n - 1);
  const glm::vec2 centre = glm::vec2(origin_) + 0.5f * float(n - 1);

  if (terrain_visible_) {
    // Pass 1: Level1 blocks (+ walls) into the frame, alpha 1.
    auto skipped = [&](const char* pass) {
      return std::find(options_.skip_passes.begin(), options_.skip_passes.end(), pass) != options_.skip_passes.end();
    };
    begin_pass("level1");
    if (!visible_blocks_.empty() && !skipped("level1")) {
      grid_program_.use();
      scene_.bind_common(grid_program_, camera, windows_);
      grid_program_.set("u_alpha", 1.0f);
      for (const auto& o : visible_blocks_) {
        grid_program_.set("u_origin", o);
        grid_program_.set("u_origin_rel", rel(o));
        block_mesh_.draw();
      }
      level1_tris = 2LL * kBlockQuads * kBlockQuads * (long long)visible_blocks_.size();
      SizeMeshes& m = meshes_for(n, band_w_);
      const GLsizeiptr wall_bytes = GLsizeiptr(m.wall_z.size() * sizeof(glm::vec2));
      glNamedBufferSubData(m.wall_heights.id(), 0, wall_bytes, m.wall_z.data());
      gl::count_upload(std::uint64_t(wall_bytes));
      grid_program_.set("u_origin", origin_);
      grid_program_.set("u_origin_rel", rel(origin_));
      glBindVertexArray(m.wall_vao.id());
      {
        const gl::ScopedDisable two_sided(GL_CULL_FACE);  // a wall is seen from inside or outside the square
        glDrawElements(GL_TRIANGLES, m.wall_indices, GL_UNSIGNED_INT, nullptr);
      }
      gl::count_draw();
      passes.push_back("level1");
    }

    // Pass 2: band into its own RGBA16F target (uv relative to the centre, beta, mask).
    const bool band_on = band_visible_ && !skipped("band");
    if (band_on) upload_beta_template(n, band_w_);
    if (!options_.band_inline) {
      begin_pass("band");
      ensure_band_target(target.width(), target.height());
    }
    if (band_on && !options_.band_inline) {  // else Level0 ignores the band target (u_band_valid), so no clear either
      const GLuint band_fbo = band_target_->fbo();
      glBindFramebuffer(GL_FRAMEBUFFER, band_fbo);
      const float clear_band[4] = {0, 0, 0, 0};
      const float clear_depth = 0.0f;
      glEnable(GL_SCISSOR_TEST);  // clears and the ring only inside the band's rectangle
      glScissor(band_rect_.x, band_rect_.y, band_rect_.z - band_rect_.x, band_rect_.w - band_rect_.y);
      glClearNamedFramebufferfv(band_fbo, GL_COLOR, 0, clear_band);
      glClearNamedFramebufferfv(band_fbo, GL_DEPTH, 0, &clear_depth);
      SizeMeshes& m = meshes_for(n, band_w_);
      band_program_.use();
      scene_.bind_common(band_program_, camera, windows_);
      glBindTextureUnit(2, beta_tex_.id());
      band_program_.set("u_beta_template", 2);
      band_program_.set("u_level1_center", centre);
      band_program_.set("u_grown_half", 0.5f * float(n - 1) + float(band_w_));
      band_program_.set("u_origin", origin_);
      band_program_.set("u_origin_rel", rel(origin_));
      glBindVertexArray(m.ring_vao.id());
      glDrawElements(GL_TRIANGLES, m.ring_indices, GL_UNSIGNED_INT, nullptr);
      gl::count_draw();
      glDisable(GL_SCISSOR_TEST);
      band_tris = m.ring_indices / 3;
      passes.push_back("band");
    }

    // Pass 3: Level0 into the frame, outside the Level1 square, depth-tested.
    begin_pass("level0");
    target.bind();
    const glm::dvec2 spacing(hf.spacing_x_m, hf.spacing_y_m);
    const glm::ivec2 eye_sample(int(std::floor(camera.position.x / spacing.x)),
                                int(std::floor(camera.position.y / spacing.y)));
    if (band_target_) {
      glBindTextureUnit(3, band_target_->color_texture());
      glBindTextureUnit(4, band_target_->depth_texture());
    }
    glBindTextureUnit(2, beta_tex_.id());
    glBindVertexArray(level0_vao_.id());
    for (auto* program : {&level0_program_, &level0_clipped_program_}) {
      const int cls = program == &level0_program_ ? 0 : 1;
      if (!draw_counts_[cls].empty() && !skipped("level0")) {
        program->use();
        scene_.bind_common(*program, camera, windows_);
        program->set("u_eye_sample", eye_sample);
        program->set("u_eye_frac", glm::vec3(camera.position.x - eye_sample.x * spacing.x,
                                             camera.position.y - eye_sample.y * spacing.y, camera.position.z));
        program->set("u_alpha", 0.5f);
        program->set("u_level1_box", box);
        program->set("u_clip_footprint", target.samples() > 1 ? 1 : 0);
        program->set("u_level1_center", centre);
        program->set("u_band", 3);
        program->set("u_band_depth", 4);
        program->set("u_band_rect", glm::vec4(band_rect_));
        program->set("u_band_valid", band_on ? 1 : 0);
        program->set("u_band_inline", options_.band_inline ? 1 : 0);
        program->set("u_beta_template", 2);
        program->set("u_grown_half", 0.5f * float(n - 1) + float(band_w_));
        program->set("u_level1_half", 0.5f * float(n - 1));
        program->set("u_near_far", glm::vec2(float(camera.near_m), float(camera.far_m)));
        program->set("u_band_tolerance_m", float(2.0 * level0_.max_error_m));
        glMultiDrawElements(GL_TRIANGLES, draw_counts_[cls].data(), GL_UNSIGNED_INT, draw_offsets_[cls].data(),
                            GLsizei(draw_counts_[cls].size()));
        gl::count_draw();
      }
    }
    for (const auto& runs : level0_runs_) level0_tris += (long long)runs.indices() / 3;
    if (level0_tris > 0) passes.push_back("level0");

    // Coverage count for next frame's size decision (results read next frame).
    // Every 4th pixel each way: 1/16 of the fragments; both counts use the same samples.
    begin_pass("count");
    constexpr int kStep = 4;
    const int cw = (target.width() + kStep - 1) / kStep, ch = (target.height() + kStep - 1) / kStep;
    glBindFramebuffer(GL_FRAMEBUFFER, count_fbo_.id());
    glNamedFramebufferParameteri(count_fbo_.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, cw);
    glNamedFramebufferParameteri(count_fbo_.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, ch);
    glViewport(0, 0, cw, ch);
    glDisable(GL_DEPTH_TEST);
    const gl::ScopedDisable no_culling(GL_CULL_FACE);
    const bool multisampled = target.samples() > 1;
    if (!count_program_.id() || count_multisampled_ != multisampled) {
      count_program_ = gl::ShaderProgram(shader_dir_, "fullscreen.vert",
                                         multisampled ? "coverage_count_ms.frag" : "coverage_count.frag");
      count_multisampled_ = multisampled;
    }
    const gl::ShaderProgram& count = count_program_;
    count.use();
    glBindTextureUnit(5, target.drawn_color_texture());
    count.set("u_color", 5);
    count.set("u_step", kStep);
    glBindVertexArray(empty_vao_.id());
    for (int k = 0; k < (skipped("count") ? 0 : 2); ++k) {
      count.set("u_threshold", k == 0 ? 0.75f : 0.25f);
      glBeginQuery(GL_SAMPLES_PASSED, queries_[parity_][k].id());
      glDrawArrays(GL_TRIANGLES, 0, 3);
      gl::count_draw();
      glEndQuery(GL_SAMPLES_PASSED);
    }
    query_pending_[parity_] = !skipped("count");
    parity_ ^= 1;
    glEnable(GL_DEPTH_TEST);
    target.bind();
  }

  stats.triangles = level0_tris + level1_tris + band_tris;
  for (size_t k = 0; k < passes.size(); ++k) stats.passes += (k ? "+" : "") + passes[k];
  stats.columns = {{"level1_n", double(n)},
                   {"level1_ratio", last_ratio_},
                   {"level0_tris", double(level0_tris)},
                   {"level1_tris", double(level1_tris)},
                   {"band_tris", double(band_tris)},
                   {"band_w", double(band_w_)},
                   {"e_x", look_at_.point.x},
                   {"e_y", look_at_.point.y},
                   {"e_hit", look_at_.hit ? 1.0 : 0.0},
                   {"level0_hidden_clusters", double(level0_hidden_clusters_)},
                   {"level1_hidden_blocks", double(level1_hidden_blocks_)},
                   {"level1_held", level1_held_ ? 1.0 : 0.0},
                   {"level1_far", far_ ? 1.0 : 0.0}};
  return stats;
}

}  // namespace ig::render

namespace ig::render {

std::optional<double> TwoLevelMethod::error_bound_px(const Camera& camera, int viewport_height_px) const {
  const auto& hf = scene_.heightfield();
  const int n = n_;
  const double x0 = origin_.x * hf.spacing_x_m, x1 = (origin_.x + n - 1) * hf.spacing_x_m;
  const double y0 = origin_.y * hf.spacing_y_m, y1 = (origin_.y + n - 1) * hf.spacing_y_m;
  const glm::dvec3& p = camera.position;
  double d;
  if (p.x > x0 && p.x < x1 && p.y > y0 && p.y < y1) {
    d = std::min({p.x - x0, x1 - p.x, p.y - y0, y1 - p.y});
  } else {
    d = p.z - hf.sample_bilinear(p.x, p.y);
  }
  d = std::max(d, camera.near_m);
  return level0_.max_error_m / d * pixels_per_radian(camera, viewport_height_px);
}

}  // namespace ig::render
