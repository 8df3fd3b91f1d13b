#include "gl/twolevel_passes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "gl/coverage_codes.h"
#include "gl/draw_pacing.h"
#include "gl/scoped_disable.h"
#include "gl/texture_units.h"
#include "gl/work_counters.h"
#include "lod/level1_selection.h"

namespace ig::gl {

TwoLevelPasses::TwoLevelPasses(const std::string& shader_dir, const TwoLevelStages& stages,
                               const lod::Level0Mesh& level0, const std::vector<float>& lift,
                               const options::TwoLevelOptions& options)
    : options_(options),
      shader_dir_(shader_dir),
      grid_program_(shader_dir, "terrain_grid.vert", stages.grid),
      level0_program_(shader_dir, "level0.vert", stages.level0),
      level0_clipped_program_(shader_dir, "level0.vert", stages.level0_clipped),
      level0_without_band_program_(shader_dir, "level0.vert", stages.level0_without_band),
      band_program_(shader_dir, "terrain_grid.vert", "band.frag"),
      level0_(level0, lift),
      level0_max_error_m_(level0.max_error_m) {
  count_fbo_ = create_framebuffer();
  glNamedFramebufferParameteri(count_fbo_.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, 1);
  glNamedFramebufferParameteri(count_fbo_.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, 1);
  empty_vao_ = create_vertex_array();
  for (auto& pair : queries_)
    for (auto& q : pair) q = create_query();
}

Level1SizeMeshes& TwoLevelPasses::meshes_for(int n, int band_w) {
  constexpr std::size_t kKept = 2;
  const std::pair<int, int> key{n, band_w};
  auto hit = std::find_if(size_meshes_.begin(), size_meshes_.end(), [&](const SizedMeshes& m) { return m.key == key; });
  if (hit == size_meshes_.end()) {
    if (size_meshes_.size() >= kKept) size_meshes_.pop_back();
    size_meshes_.push_back(
        {key, std::make_unique<Level1SizeMeshes>(n, band_w, std::min(options_.band_stride, std::max(band_w, 1)))});
    hit = size_meshes_.end() - 1;
  }
  std::rotate(size_meshes_.begin(), hit, hit + 1);
  return *size_meshes_.front().meshes;
}

bool TwoLevelPasses::skipped(const char* pass) const {
  return std::find(options_.skip_passes.begin(), options_.skip_passes.end(), pass) != options_.skip_passes.end();
}

double TwoLevelPasses::read_previous_ratio() {
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

TwoLevelDrawn TwoLevelPasses::draw(const lod::TwoLevelSelection& sel, const TwoLevelDrawContext& ctx,
                                   const RenderTarget& target) {
  TwoLevelDrawn drawn;
  if (!sel.terrain_visible) return drawn;
  draw_level1(sel, ctx, drawn);
  const bool band_on = draw_band(sel, ctx, target, drawn);
  draw_level0(sel, ctx, target, band_on, drawn);
  ctx.begin_pass("count", false);
  count(target);
  return drawn;
}

namespace {
glm::vec3 relative(glm::ivec2 s, const TwoLevelDrawContext& ctx) {
  return glm::vec3(glm::dvec3(s.x * ctx.spacing.x, s.y * ctx.spacing.y, 0.0) - ctx.eye);
}
}  // namespace

void TwoLevelPasses::draw_level1(const lod::TwoLevelSelection& sel, const TwoLevelDrawContext& ctx,
                                 TwoLevelDrawn& drawn) {
  ctx.begin_pass("level1", true);
  if (sel.visible_blocks.empty() || skipped("level1")) return;
  grid_program_.use();
  ctx.bind_common(grid_program_);
  grid_program_.set("u_alpha", coverage::kLevel1);
  for (const auto& o : sel.visible_blocks) {
    grid_program_.set("u_origin", o);
    grid_program_.set("u_origin_rel", relative(o, ctx));
    ctx.draw_block();
  }
  constexpr long long kBlockQuads = lod::kLevel1BlockQuads;
  drawn.level1_tris = 2LL * kBlockQuads * kBlockQuads * (long long)sel.visible_blocks.size();
  Level1SizeMeshes& m = meshes_for(sel.n, sel.band_w);
  m.upload_wall_heights(sel.wall_z, sel.wall_version);
  grid_program_.set("u_origin", sel.origin);
  grid_program_.set("u_origin_rel", relative(sel.origin, ctx));
  glBindVertexArray(m.wall_vao.id());
  {
    const ScopedDisable two_sided(GL_CULL_FACE);  // a wall is seen from inside or outside the square
    draw_indexed_triangles(GL_UNSIGNED_INT, 0, m.wall_indices);
  }
  drawn.passes.push_back("level1");
}

bool TwoLevelPasses::draw_band(const lod::TwoLevelSelection& sel, const TwoLevelDrawContext& ctx,
                               const RenderTarget& target, TwoLevelDrawn& drawn) {
  const int n = sel.n;
  const bool band_on = sel.band_visible && !skipped("band");
  if (band_on) beta_.update(n, sel.band_w, options_.gaussian_beta);
  if (options_.band_inline) return band_on;  // Level0 marches the band itself: no target, no clear
  ctx.begin_pass("band", true);
  if (!band_target_ || band_target_->width() != target.width() || band_target_->height() != target.height())
    band_target_ = std::make_unique<RenderTarget>(target.width(), target.height(), GL_RGBA16F);
  if (!band_on) return false;  // Level0 ignores the band target (u_band_valid)
  const GLuint band_fbo = band_target_->fbo();
  glBindFramebuffer(GL_FRAMEBUFFER, band_fbo);
  const float clear_band[4] = {0, 0, 0, 0};
  const float clear_depth = 0.0f;
  const glm::ivec4& r = sel.band_rect;
  glEnable(GL_SCISSOR_TEST);  // clears and the ring only inside the band's rectangle
  glScissor(r.x, r.y, r.z - r.x, r.w - r.y);
  glClearNamedFramebufferfv(band_fbo, GL_COLOR, 0, clear_band);
  glClearNamedFramebufferfv(band_fbo, GL_DEPTH, 0, &clear_depth);
  Level1SizeMeshes& m = meshes_for(n, sel.band_w);
  band_program_.use();
  ctx.bind_common(band_program_);
  glBindTextureUnit(unit(TextureUnit::kBetaTemplate), beta_.texture().id());
  band_program_.set("u_beta_template", unit(TextureUnit::kBetaTemplate));
  band_program_.set("u_level1_center", glm::vec2(sel.origin) + 0.5f * float(n - 1));
  band_program_.set("u_grown_half", 0.5f * float(n - 1) + float(sel.band_w));
  band_program_.set("u_origin", sel.origin);
  band_program_.set("u_origin_rel", relative(sel.origin, ctx));
  glBindVertexArray(m.ring_vao.id());
  draw_indexed_triangles(GL_UNSIGNED_INT, 0, m.ring_indices);
  glDisable(GL_SCISSOR_TEST);
  drawn.band_tris = m.ring_indices / 3;
  drawn.passes.push_back("band");
  return true;
}

void TwoLevelPasses::draw_level0(const lod::TwoLevelSelection& sel, const TwoLevelDrawContext& ctx,
                                 const RenderTarget& target, bool band_on, TwoLevelDrawn& drawn) {
  const int n = sel.n;
  ctx.begin_pass("level0", true);
  target.bind();
  const glm::ivec2 eye_sample(int(std::floor(ctx.eye.x / ctx.spacing.x)), int(std::floor(ctx.eye.y / ctx.spacing.y)));
  if (band_target_) {
    glBindTextureUnit(unit(TextureUnit::kBandColor), band_target_->color_texture());
    glBindTextureUnit(unit(TextureUnit::kBandDepth), band_target_->depth_texture());
  }
  glBindTextureUnit(unit(TextureUnit::kBetaTemplate), beta_.texture().id());
  glBindVertexArray(level0_.vao.id());
  const ShaderProgram* programs[3] = {&level0_program_, &level0_clipped_program_, &level0_without_band_program_};
  for (int cls = 0; cls < 3; ++cls) {
    const ShaderProgram& program = *programs[cls];
    const lod::IndexRuns& runs = sel.level0_runs[cls];
    if (runs.count.empty() || skipped("level0")) continue;
    // As glMultiDrawElements takes them (counts, byte offsets into the index buffer).
    draw_counts_.assign(runs.count.begin(), runs.count.end());
    draw_offsets_.clear();
    for (auto first : runs.first)
      draw_offsets_.push_back(reinterpret_cast<const void*>(std::uintptr_t(first) * sizeof(std::uint32_t)));
    program.use();
    ctx.bind_common(program);
    program.set("u_eye_sample", eye_sample);
    program.set("u_eye_frac", glm::vec3(ctx.eye.x - eye_sample.x * ctx.spacing.x,
                                        ctx.eye.y - eye_sample.y * ctx.spacing.y, ctx.eye.z));
    program.set("u_alpha", coverage::kLevel0);
    program.set("u_level1_box", glm::vec4(sel.origin.x, sel.origin.y, sel.origin.x + n - 1, sel.origin.y + n - 1));
    program.set("u_clip_footprint", target.samples() > 1 ? 1 : 0);
    program.set("u_level1_center", glm::vec2(sel.origin) + 0.5f * float(n - 1));
    program.set("u_band", unit(TextureUnit::kBandColor));
    program.set("u_band_depth", unit(TextureUnit::kBandDepth));
    program.set("u_band_rect", glm::vec4(sel.band_rect));
    program.set("u_band_valid", band_on ? 1 : 0);
    program.set("u_band_inline", options_.band_inline ? 1 : 0);
    program.set("u_beta_template", unit(TextureUnit::kBetaTemplate));
    program.set("u_grown_half", 0.5f * float(n - 1) + float(sel.band_w));
    program.set("u_level1_half", 0.5f * float(n - 1));
    program.set("u_near_far", glm::vec2(float(ctx.near_m), float(ctx.far_m)));
    program.set("u_band_tolerance_m", float(lod::BandRing::tolerance_for(level0_max_error_m_)));
    program.set("u_band_window_per_m", float(lod::BandRing::kWindowPerMetre));
    draw_indexed_runs(draw_counts_, draw_offsets_);
  }
  for (const auto& runs : sel.level0_runs) drawn.level0_tris += (long long)runs.indices() / 3;
  if (drawn.level0_tris > 0) drawn.passes.push_back("level0");
}

void TwoLevelPasses::count(const RenderTarget& target) {
  // Every 4th pixel each way: 1/16 of the fragments; both counts use the same samples.
  constexpr int kStep = 4;
  const int cw = (target.width() + kStep - 1) / kStep, ch = (target.height() + kStep - 1) / kStep;
  glBindFramebuffer(GL_FRAMEBUFFER, count_fbo_.id());
  glNamedFramebufferParameteri(count_fbo_.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, cw);
  glNamedFramebufferParameteri(count_fbo_.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, ch);
  glViewport(0, 0, cw, ch);
  glDisable(GL_DEPTH_TEST);
  const ScopedDisable no_culling(GL_CULL_FACE);
  const bool multisampled = target.samples() > 1;
  if (!count_program_.id() || count_multisampled_ != multisampled) {
    count_program_ = ShaderProgram(shader_dir_, "fullscreen.vert",
                                   multisampled ? "coverage_count_ms.frag" : "coverage_count.frag");
    count_multisampled_ = multisampled;
  }
  const ShaderProgram& program = count_program_;
  program.use();
  glBindTextureUnit(unit(TextureUnit::kFrameColor), target.drawn_color_texture());
  program.set("u_color", unit(TextureUnit::kFrameColor));
  program.set("u_step", kStep);
  glBindVertexArray(empty_vao_.id());
  const bool on = !skipped("count");
  for (int k = 0; k < (on ? 2 : 0); ++k) {
    program.set("u_threshold", k == 0 ? coverage::kAtLeastLevel1 : coverage::kAnyTerrain);
    glBeginQuery(GL_SAMPLES_PASSED, queries_[parity_][k].id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    count_draw();
    glEndQuery(GL_SAMPLES_PASSED);
  }
  query_pending_[parity_] = on;
  parity_ ^= 1;
  glEnable(GL_DEPTH_TEST);
  target.bind();
}

}  // namespace ig::gl
