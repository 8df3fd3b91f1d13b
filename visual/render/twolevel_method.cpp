#include "render/twolevel_method.h"

#include <algorithm>
#include <utility>

#include "lod/level0_budget.h"
#include "lod/level0_clusters.h"
#include "lod/level0_envelope.h"
#include "lod/level1_selection.h"
#include "render/scene_level0.h"

namespace ig::render {
namespace {

// "auto" (0) without a display to derive it from: the reference display's budget.
TwoLevelOptions with_budget(TwoLevelOptions o) {
  if (o.level0_budget == 0) o.level0_budget = lod::level0_budget_for_display(0.0);
  return o;
}

}  // namespace

TwoLevelMethod::TwoLevelMethod(TerrainScene& scene, const std::string& shader_dir, TwoLevelOptions options)
    : scene_(scene),
      options_(with_budget(std::move(options))),
      pyramid_(scene.height_pyramid()),
      block_mesh_(lod::kLevel1BlockQuads) {
  const auto& hf = scene.heightfield();
  // Level0 on the overview beyond the texture limit.
  lod::Level0Mesh level0 = lod::z_ordered(build_scene_level0(
      scene, lod::Level0Options{options_.level0_budget, 0.0, scene.earth_radius_m(), options_.level0_whole_error}));
  std::vector<float> lift(level0.samples.size(), 0.0f);
  if (options_.level0_envelope) {
    lift = lod::level0_upper_envelope(level0, hf, scene.earth_radius_m()).lift_m;
    for (size_t v = 0; v < lift.size(); ++v) level0.positions[v].z += lift[v];  // the walls' height query
  }
  selector_ = std::make_unique<lod::TwoLevelSelector>(hf, pyramid_, std::move(level0), options_);
  const gl::TwoLevelStages stages{scene.shading_stages({"terrain.frag"}),
                                  scene.shading_stages({"level0_blend.frag", "level0.frag"}),
                                  scene.shading_stages({"level0_blend.frag", "level0_clipped.frag"}),
                                  scene.shading_stages({"level0_no_band.frag", "level0.frag"})};
  passes_ = std::make_unique<gl::TwoLevelPasses>(shader_dir, stages, selector_->level0(), lift, options_);
  windows_ = scene.claim_windows();  // this channel's height (and imagery) window
}

TwoLevelMethod::~TwoLevelMethod() { scene_.release_windows(windows_); }

std::vector<std::string> TwoLevelMethod::pass_names() const {
  if (options_.band_inline) return {"level1", "level0", "count"};  // the band is shaded inside level0
  return {"level1", "band", "level0", "count"};
}

std::vector<std::string> TwoLevelMethod::column_names() const {
  return {"level1_n", "level1_ratio", "level0_tris", "level1_tris", "band_tris", "band_w", "e_x", "e_y", "e_hit",
          "level0_hidden_clusters", "level1_hidden_blocks", "hidden_boxes", "level1_held", "level1_far"};
}

lod::SceneRequests TwoLevelMethod::update(const Camera& camera) {
  const Frustum frustum = frustum_of(camera);
  lod::TwoLevelView view;
  view.position = camera.position;
  view.forward = camera.forward();
  view.up = camera.up();
  view.earth_radius_m = camera.earth_radius_m;
  view.near_m = camera.near_m;
  view.far_m = camera.far_m;
  view.viewport = viewport_;
  view.pixels_per_radian = pixels_per_radian(camera, viewport_.y);
  view.box_in_view = [&](const glm::dvec3& lo, const glm::dvec3& hi) { return frustum.intersects_box(lo, hi); };
  view.pixel_ray = [&](double px, double py) { return camera.pixel_ray(px, py, viewport_.x, viewport_.y); };
  view.screen_rect = [&](const glm::dvec3& lo, const glm::dvec3& hi) {
    return screen_rect_of_box(camera, lo, hi, viewport_.x, viewport_.y);
  };
  // Paged heights, live (the scene's wait_for_pages() false): a square whose
  // heights (or its height window's) are not all resident is refused, and
  // the scene step asks for them, first of all its requests.
  std::vector<std::pair<glm::ivec2, glm::ivec2>> asked;
  lod::Level1Paging paging;
  paging.no_wait = scene_.heightfield().paged && !scene_.wait_for_pages();
  paging.ready = [&](glm::ivec2 lo, glm::ivec2 hi, glm::ivec2 window_centre) {
    asked.emplace_back(lo, hi);
    if (!scene_.samples_resident(lo, hi)) return false;
    const auto window = scene_.window_samples(windows_, window_centre);
    if (!window) return true;
    asked.push_back(*window);
    return scene_.samples_resident(window->first, window->second);
  };
  const double ratio = passes_->read_previous_ratio();
  lod::SceneRequests requests = selector_->select(view, ratio, paging).scene_requests;
  requests.sample_rects.insert(requests.sample_rects.begin(), asked.begin(), asked.end());
  requests.window_set = windows_;  // this channel's height window follows Level1
  return requests;
}

MethodFrameStats TwoLevelMethod::draw(const Camera& camera, const gl::RenderTarget& target) {
  const auto& hf = scene_.heightfield();
  const auto& sel = selection();
  gl::TwoLevelDrawContext ctx;
  ctx.eye = camera.position;
  ctx.near_m = camera.near_m;
  ctx.far_m = camera.far_m;
  ctx.spacing = {hf.spacing_x_m, hf.spacing_y_m};
  ctx.bind_common = [&](const gl::ShaderProgram& program) { scene_.bind_common(program, camera, windows_); };
  ctx.begin_pass = [this](std::string_view pass, bool count_samples) { begin_pass(pass, count_samples); };
  ctx.draw_block = [this] { block_mesh_.draw(); };
  const gl::TwoLevelDrawn drawn = passes_->draw(sel, ctx, target);

  MethodFrameStats stats;
  stats.triangles = drawn.level0_tris + drawn.level1_tris + drawn.band_tris;
  for (size_t k = 0; k < drawn.passes.size(); ++k) stats.passes += (k ? "+" : "") + drawn.passes[k];
  stats.columns = {{"level1_n", double(sel.n)},
                   {"level1_ratio", sel.last_ratio},
                   {"level0_tris", double(drawn.level0_tris)},
                   {"level1_tris", double(drawn.level1_tris)},
                   {"band_tris", double(drawn.band_tris)},
                   {"band_w", double(sel.band_w)},
                   {"e_x", sel.look_at.point.x},
                   {"e_y", sel.look_at.point.y},
                   {"e_hit", sel.look_at.hit ? 1.0 : 0.0},
                   {"level0_hidden_clusters", double(sel.level0_hidden_clusters)},
                   {"level1_hidden_blocks", double(sel.level1_hidden_blocks)},
                   {"hidden_boxes", double(sel.level0_hidden_clusters + sel.level1_hidden_blocks)},
                   {"level1_held", sel.held ? 1.0 : 0.0},
                   {"level1_far", sel.far ? 1.0 : 0.0}};
  return stats;
}

std::optional<double> TwoLevelMethod::error_bound_px(const Camera& camera, int viewport_height_px) const {
  const auto& hf = scene_.heightfield();
  const auto& sel = selection();
  const int n = sel.n;
  const double x0 = sel.origin.x * hf.spacing_x_m, x1 = (sel.origin.x + n - 1) * hf.spacing_x_m;
  const double y0 = sel.origin.y * hf.spacing_y_m, y1 = (sel.origin.y + n - 1) * hf.spacing_y_m;
  const glm::dvec3& p = camera.position;
  double d;
  if (p.x > x0 && p.x < x1 && p.y > y0 && p.y < y1) {
    d = std::min({p.x - x0, x1 - p.x, p.y - y0, y1 - p.y});
  } else {
    d = p.z - hf.sample_bilinear(p.x, p.y);
  }
  d = std::max(d, camera.near_m);
  return level0().max_error_m / d * pixels_per_radian(camera, viewport_height_px);
}

}  // namespace ig::render
