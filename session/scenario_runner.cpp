#include "session/scenario_runner.h"

#include <algorithm>
#include <cmath>

#include "gl/shader_program.h"
#include "lod/level0_budget.h"
#include "models/model_table.h"
#include "lod/look_at_point.h"
#include "render/twolevel_method.h"
#include "session/scene_setup.h"
#include "terrain/paged_heights.h"
#include "terrain/ray_cast.h"
#include "session/view_step.h"
#include "stats/timing.h"

namespace ig::session {
namespace {
using Clock = stats::WallClock;
using stats::ms_since;
}  // namespace

ScenarioRunner::ScenarioRunner(io::Scenario scenario, const RunOptions& options)
    : scenario_(std::move(scenario)), options_(options) {
  auto& r = scenario_.render;
  if (options.width) r.width = *options.width;
  if (options.height) r.height = *options.height;
  if (options.method) r.method = *options.method;
  if (options.vsync) r.vsync = *options.vsync;
  if (options_.shader_dir.empty()) options_.shader_dir = gl::default_shader_dir();
  if (r.twolevel.level0_budget == 0) {  // "auto": from the finest channel
    double finest = 0.0;
    for (const auto& c : scenario_.channels)
      finest = std::max(finest, lod::pixels_per_radian(r.height, c.fov_y_deg.value_or(r.fov_y_deg)));
    r.twolevel.level0_budget = lod::level0_budget_for_display(finest);
  }

  auto t0 = Clock::now();
  heightfield_ = load_terrain(scenario_.terrain);
  load_ms_ = ms_since(t0);
  path_ = std::make_unique<io::PathInterpolator>(place_path(scenario_.path, heightfield_));
  if (!scenario_.entities.empty()) scripted_ = std::make_unique<ScenarioEntities>(scenario_.entities, heightfield_);
  geolocation_ = environment::TerrainGeolocation::make(heightfield_);
  if (r.shading.time_utc && !r.shading.sun_direction) {
    if (!geolocation_)
      throw io::ScenarioError((scenario_.source_path.empty() ? "" : scenario_.source_path + ": ") +
                              "environment.time_utc: the terrain (" + heightfield_.source +
                              ") has no georeference to place the sun; use a georeferenced DEM or "
                              "terrain.generator.origin, or give render.sun_direction");
    sun_tracker_.emplace(*r.shading.time_utc);
    clock_start_ = *r.shading.time_utc;
  }
  frame_count_ = options.frames ? *options.frames : io::scenario_frame_count(scenario_);

  gl::ContextOptions co;
  co.headless = options.headless;
  co.width = r.width;
  co.height = r.height;
  co.fullscreen = options.fullscreen;
  co.vsync = r.vsync;
  co.title = "ig - " + scenario_.name;
  context_ = gl::create_context(co);
  r.antialiasing = resolve_antialiasing(r.antialiasing, context_->gl_renderer());
  // A multisampled frame shades its samples where they are drawn.
  if (r.antialiasing == "msaa") r.shading.deferred_shading = false;

  scene_ = std::make_unique<render::TerrainScene>(heightfield_, r.shading, r.imagery, scenario_.terrain.texture_limit,
                                                  std::size_t(scenario_.terrain.imagery_budget_mb) << 20);
  scene_->set_earth_radius(earth_radius_for(r, scenario_.terrain, heightfield_));
  scene_->enable_height_window(scenario_.terrain.height_window);
  scene_->set_wait_for_pages(scenario_.terrain.wait_for_pages);
  update_sun(0.0, pose_at(0.0).position);

  for (const auto& spec : scenario_.channels) {
    ChannelView v;
    v.spec = spec;
    v.target = make_frame_target(r, r.width, r.height);
    v.method = render::make_method(r.method, *scene_, options_.shader_dir, r.method_options());
    v.renderer = std::make_unique<render::FrameRenderer>(*scene_, *v.method, options_.shader_dir);
    v.renderer->set_pass_times(options_.pass_times);
    channels_.push_back(std::move(v));
  }
  prefetch_first_window();
}

std::string resolve_antialiasing(const std::string& setting, const std::string& gl_renderer) {
  if (setting != "auto") return setting;
  for (const char* cpu : {"llvmpipe", "softpipe", "Software Rasterizer", "SwiftShader"})
    if (gl_renderer.find(cpu) != std::string::npos) return "fxaa";
  return "msaa";
}

std::unique_ptr<gl::RenderTarget> make_frame_target(const io::RenderSpec& r, int width, int height) {
  const bool msaa = r.antialiasing == "msaa";
  return std::make_unique<gl::RenderTarget>(width, height, GL_RGBA8, msaa ? r.msaa_samples : 1,
                                            r.antialiasing == "fxaa");
}

io::Pose ScenarioRunner::pose_at(double t_s) const { return path_->sample(t_s); }

render::Camera ScenarioRunner::camera_for(const io::Pose& pose, const ChannelView& ch) const {
  const auto& r = scenario_.render;
  render::Camera c;
  // The view's entity (the ownship unless a host put it on another one).
  io::Pose base = pose;
  if (ch.spec.entity != 0 && entity_lookup_)
    if (const auto e = entity_lookup_(ch.spec.entity)) base = *e;
  const auto& o = ch.spec.eye_offset_m;  // x forward, y right, z down
  c.position = base.position + io::forward_of(base.attitude) * o[0] + io::right_of(base.attitude) * o[1] -
               io::up_of(base.attitude) * o[2];
  c.attitude = io::apply_view_offset(
      base.attitude, io::Hpr{ch.spec.heading_offset_deg, ch.spec.pitch_offset_deg, ch.spec.roll_offset_deg});
  c.fov_y_deg = ch.spec.fov_y_deg.value_or(r.fov_y_deg);
  c.aspect = double(r.width) / double(r.height);
  c.near_m = r.near_m;
  c.far_m = r.far_m;
  return c;
}

// The members' GL objects are deleted after this body, in this runner's context.
ScenarioRunner::~ScenarioRunner() {
  if (context_) context_->make_current();
}

void ScenarioRunner::set_entities(std::vector<render::EntityInstance> entities) { host_entities_ = std::move(entities); }

void ScenarioRunner::draw_entities(std::vector<render::EntityInstance> entities) {
  if (!entities_) {
    if (entities.empty()) return;
    context_->make_current();
    // The default model table (bin/models or PREFIX/share/ig/models); without
    // it every type is a box, and each is said once.
    std::optional<models::ModelTable> table;
    const std::string dir = gl::installed_data_dir("models", "default_models.json");
    if (!dir.empty()) table = models::load_model_table(dir + "/default_models.json");
    entities_ = std::make_unique<render::EntityRenderer>(options_.shader_dir, std::move(table));
    for (auto& ch : channels_) ch.renderer->set_entities(entities_.get());
  }
  entities_->set_instances(std::move(entities));
}

FrameResult ScenarioRunner::render_frame(int k) {
  const double t = k * scenario_.time_step_s;
  const auto t0 = Clock::now();
  const io::Pose pose = pose_at(t);
  return render_pose(k, t, pose, ms_since(t0));
}

FrameResult ScenarioRunner::render_pose(int k, double sim_time_s, const io::Pose& pose, double pose_ms) {
  context_->make_current();
  FrameResult f;
  f.frame = k;
  f.sim_time_s = sim_time_s;
  f.pose = pose;
  f.pose_ms = pose_ms;
  const terrain::HeightTileCache* pages = heightfield_.paged ? heightfield_.paged->cache.get() : nullptr;
  const auto before = pages ? pages->stats() : terrain::HeightTileCache::Stats{};
  const render::ImageryWindowTexture* imagery = scene_->imagery_window();
  const auto imagery_before = imagery ? imagery->stats() : render::ImageryWindowTexture::Stats{};
  const auto imagery_pages_before = imagery ? imagery->cache().stats() : terrain::RgbTileCache::Stats{};
  update_sun(sim_time_s, pose.position);
  scene_->set_time(sim_time_s);  // the waves drift with the scene's clock
  f.visibility_m = scene_->shading().fog_visibility_m;
  // This frame's entities: the scenario's at this time, then the host's.
  std::vector<render::EntityInstance> entities;
  if (scripted_) entities = scripted_->at(sim_time_s, pose);
  entities.insert(entities.end(), host_entities_.begin(), host_entities_.end());
  draw_entities(std::move(entities));
  for (auto& ch : channels_) {
    const auto t0 = Clock::now();
    ch.camera = camera_for(f.pose, ch);
    ch.last = render_view(*scene_, *ch.renderer, ch.camera, *ch.target);
    ch.render_ms = ms_since(t0);
  }
  if (pages) {
    const auto after = pages->stats();
    f.page_waits = after.misses - before.misses;
    f.page_ins = after.prefetched - before.prefetched;
  }
  if (imagery) {
    const auto after = imagery->stats();
    const auto pages_after = imagery->cache().stats();
    f.imagery_held = after.held_moves - imagery_before.held_moves;
    f.imagery_missing = after.missing_tiles - imagery_before.missing_tiles;
    f.imagery_page_ins = pages_after.prefetched - imagery_pages_before.prefetched;
    f.imagery_page_waits = pages_after.misses - imagery_pages_before.misses;
  }
  return f;
}

void ScenarioRunner::update_sun(double sim_time_s, const glm::dvec3& eye) {
  const glm::dvec3 local = eye - scene_->world_origin();
  const auto place = geolocation_ ? geolocation_->locate(glm::dvec2(local)) : std::nullopt;
  if (!sun_tracker_) {
    // A fixed direction in terrain-local axes: only its angles change.
    sun_ = environment::angles_of(glm::dvec3(scene_->sky_light().sun_direction), place ? place->grid_north_deg : 0.0);
    return;
  }
  if (!place) return;  // the transform failed out here: the sun stays where it was
  const environment::SunPosition& p =
      sun_tracker_->at(clock_runs_ ? sim_time_s - clock_zero_s_ : 0.0, {place->latitude_deg, place->longitude_deg, std::isfinite(local.z) ? local.z : 0.0});
  sun_ = {p.elevation_deg, p.azimuth_deg};
  scene_->set_sun_direction(
      glm::vec3(environment::local_direction(p.azimuth_deg, p.elevation_deg, place->grid_north_deg)));
}

bool ScenarioRunner::set_time_of_day(const options::UtcDateTime& time, double at_s, bool runs) {
  if (!geolocation_) return false;
  sun_tracker_.emplace(time);
  clock_start_ = time;
  clock_zero_s_ = at_s;
  clock_runs_ = runs;
  return true;
}

void ScenarioRunner::prefetch_first_window() {
  if (scene_->imagery_window()) {
    // Imagery beyond one texture: its window filled at load (4096^2 RGB is
    // 50 MB, paged from the file) where the first frame's Level1 will be:
    // around the first channel's look-at point (as the two-level method
    // finds it), so frame 0 moves it by a little, within the tiles of margin
    // loaded with it, instead of holding it for a jump.
    const render::Camera cam = scene_->local_camera(camera_for(pose_at(0.0), channels_.front()));
    const auto e = lod::find_look_at_point(heightfield_, scene_->height_pyramid(), cam.position, cam.forward(), cam.up(),
                                           cam.earth_radius_m);
    scene_->place_imagery_window(glm::ivec2(int(std::lround(e.point.x / heightfield_.spacing_x_m)),
                                            int(std::lround(e.point.y / heightfield_.spacing_y_m))));
  }
  const render::HeightWindowTexture* window = scene_->height_window();
  if (!heightfield_.paged || !window) return;
  // The window around the first pose, loaded before the first frame (it is
  // part of the load-to-first-frame time, not a frame's wait).
  const io::Pose pose = pose_at(0.0);
  const glm::dvec3 p = pose.position - scene_->world_origin();
  window->prefetch_around(glm::ivec2(int(p.x / heightfield_.spacing_x_m), int(p.y / heightfield_.spacing_y_m)));
  // And the tiles under the views (the two-level method's coverage rays: 12 x 9 a view).
  const auto& r = scenario_.render;
  for (const auto& ch : channels_) {
    const render::Camera cam = scene_->local_camera(camera_for(pose, ch));
    std::vector<glm::dvec3> hits;
    for (int y = 0; y < 9; ++y)
      for (int x = 0; x < 12; ++x)
        if (const auto hit = terrain::cast_ray(heightfield_, scene_->height_pyramid(), cam.position,
                                               cam.pixel_ray((x + 0.5) * r.width / 12, (y + 0.5) * r.height / 9,
                                                             r.width, r.height),
                                               cam.far_m))
          hits.push_back(hit->point);
    scene_->prefetch_heights(hits);
    // Level1 and its band around the look-at point (the centre ray): up to
    // a 4097-sample square.
    if (const auto e = terrain::cast_ray(heightfield_, scene_->height_pyramid(), cam.position,
                                         cam.pixel_ray(0.5 * r.width, 0.5 * r.height, r.width, r.height), cam.far_m)) {
      const glm::ivec2 c(int(e->point.x / heightfield_.spacing_x_m), int(e->point.y / heightfield_.spacing_y_m));
      scene_->prefetch_samples(c - 2048, c + 2048);
    }
  }
  heightfield_.paged->cache->wait_idle();
}

std::vector<stats::Cell> frame_log_row(const FrameResult& f, const ChannelView& ch, double readback_ms,
                                       double present_ms) {
  const io::Hpr hpr = io::hpr_from_attitude(f.pose.attitude);
  const auto& m = ch.last.method;
  std::vector<stats::Cell> row = {
      {"frame", f.frame},
      {"channel", ch.spec.name},
      {"sim_time_s", f.sim_time_s},
      {"wall_ms", f.pose_ms + ch.render_ms + readback_ms + present_ms},
      {"pose_ms", f.pose_ms},
      {"lod_ms", ch.last.timings.lod_ms},
      {"terrain_ms", ch.last.timings.terrain_ms},
      {"sky_ms", ch.last.timings.sky_ms},
      {"clouds_ms", ch.last.timings.clouds_ms},
      {"resolve_ms", ch.last.timings.resolve_ms},
      {"readback_ms", readback_ms},
      {"present_ms", present_ms},
      {"triangles", m.triangles},
      {"passes", m.passes},
      {"x_m", f.pose.position.x},
      {"y_m", f.pose.position.y},
      {"z_m", f.pose.position.z},
      {"heading_deg", hpr.heading_deg},
      {"pitch_deg", hpr.pitch_deg},
      {"roll_deg", hpr.roll_deg},
      {"visibility_m", f.visibility_m},
  };
  if (f.page_waits >= 0) {  // paged heights
    row.emplace_back("page_waits", f.page_waits);
    row.emplace_back("page_ins", f.page_ins);
  }
  if (f.imagery_held >= 0) {  // paged imagery
    row.emplace_back("imagery_held", f.imagery_held);
    row.emplace_back("imagery_missing", f.imagery_missing);
    row.emplace_back("imagery_page_ins", f.imagery_page_ins);
    row.emplace_back("imagery_page_waits", f.imagery_page_waits);
  }
  for (const auto& [name, value] : m.columns) row.emplace_back(name, value);
  append_work_columns(row, ch.last, /*per_pass=*/true);
  return row;
}

void append_work_columns(std::vector<stats::Cell>& row, const render::ViewResult& v, bool per_pass) {
  auto n = [](std::uint64_t x) { return static_cast<long long>(x); };
  row.emplace_back("vs_invocations", n(v.total.vs_invocations));
  row.emplace_back("fs_invocations", n(v.total.fs_invocations));
  row.emplace_back("primitives", n(v.total.primitives));
  row.emplace_back("draw_calls", n(v.total.draw_calls));
  row.emplace_back("upload_bytes", n(v.total.bytes_uploaded));
  if (!per_pass) return;
  for (const auto& p : v.passes) {
    row.emplace_back(p.name + "_vs", n(p.vs_invocations));
    row.emplace_back(p.name + "_fs", n(p.fs_invocations));
    row.emplace_back(p.name + "_prims", n(p.primitives));
    row.emplace_back(p.name + "_draws", n(p.draw_calls));
    row.emplace_back(p.name + "_passed", n(p.samples_passed));
    if (p.ms >= 0.0) row.emplace_back(p.name + "_pass_ms", p.ms);
    if (p.name == "entities") {  // the entity pass's own counts (docs/entities.md)
      row.emplace_back("entities_drawn", n(v.entities.in_view));
      row.emplace_back("entities_culled", n(v.entities.culled));
      row.emplace_back("entities_over_budget", n(v.entities.over_budget));
    }
  }
}

void ScenarioRunner::rebuild_method(const options::TwoLevelOptions& twolevel) {
  context_->make_current();
  scenario_.render.twolevel = twolevel;
  for (auto& ch : channels_) {
    auto method = render::make_method(scenario_.render.method, *scene_, options_.shader_dir, scenario_.render.method_options());
    ch.renderer->set_method(*method);  // the renderer (sky program, queries) is kept
    ch.method = std::move(method);
  }
}

void ScenarioRunner::present() {
  context_->make_current();
  if (!channels_.empty()) {
    const auto& t = *channels_.front().target;
    context_->present(t.fbo(), t.width(), t.height());
  }
}

}  // namespace ig::session
