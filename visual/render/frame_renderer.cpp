#include "render/frame_renderer.h"

#include "gl/frame_state.h"
#include "stats/timing.h"
#include "terrain/back_faces_hidden.h"

namespace ig::render {
namespace {
using Clock = stats::WallClock;
using stats::ms_since;
// The work counters' passes: the method's, deferred shading's, its water
// pass (scenes with water only), the sky and the anti-aliasing post pass (0
// where the frame has none); the clouds after the sky in a scene with them.
std::vector<std::string> pass_names_of(const TerrainMethod& method, const TerrainScene& scene, bool entities,
                                       bool clouds) {
  auto names = method.pass_names();
  names.push_back("shade");
  if (scene.has_water()) names.push_back("water");
  if (entities) names.push_back("entities");
  names.push_back("sky");
  if (clouds || !scene.clouds().empty()) names.push_back("clouds");
  names.push_back("aa");
  return names;
}
}  // namespace

FrameRenderer::FrameRenderer(const TerrainScene& scene, TerrainMethod& method, const std::string& shader_dir)
    : scene_(scene),
      method_(&method),
      shader_dir_(shader_dir),
      sky_(shader_dir),
      post_filter_(shader_dir),
      recorder_(pass_names_of(method, scene, false, false)) {
  scene_had_clouds_ = !scene_.clouds().empty();
  method_->set_pass_recorder(&recorder_);
  take_shading_settings();
}

void FrameRenderer::take_shading_settings() {
  deferred_ = scene_.deferred_shading();
  const auto stages = deferred_ ? scene_.deferred_shade_stages() : std::vector<std::string>{};
  if (stages != deferred_shade_stages_) {  // e.g. a method switch: the same program
    deferred_shade_stages_ = stages;
    deferred_shade_program_ =
        deferred_ ? gl::ShaderProgram(shader_dir_, "fullscreen.vert", stages) : gl::ShaderProgram();
  }
  // Water over deferred shading, in a pass of its own (forward shading
  // shades it in the terrain passes).
  std::vector<std::string> water = deferred_ ? scene_.water_mask_stages() : std::vector<std::string>{};
  if (!water.empty()) {
    const auto shade = scene_.water_shade_stages();
    water.insert(water.end(), shade.begin(), shade.end());
  }
  if (water == water_stages_) return;
  water_stages_ = water;
  water_.reset();
  water_mask_program_ = gl::ShaderProgram();
  water_shade_program_ = gl::ShaderProgram();
  if (water.empty()) return;
  water_ = std::make_unique<gl::WaterPass>();
  water_mask_program_ = gl::ShaderProgram(shader_dir_, "fullscreen.vert", scene_.water_mask_stages());
  water_shade_program_ = gl::ShaderProgram(shader_dir_, "fullscreen.vert", scene_.water_shade_stages());
}

FrameRenderer::~FrameRenderer() { method_->set_pass_recorder(nullptr); }

void FrameRenderer::set_method(TerrainMethod& method) {
  method_->set_pass_recorder(nullptr);
  method_ = &method;
  if (auto names = pass_names_of(method, scene_, entities_ != nullptr, clouds_may_come_);
      names != recorder_.pass_names())
    recorder_.reset_passes(std::move(names));
  method_->set_pass_recorder(&recorder_);
  take_shading_settings();
}

void FrameRenderer::set_entities(EntityRenderer* entities) {
  entities_ = entities;
  update_pass_names();
}

void FrameRenderer::update_pass_names() {
  scene_had_clouds_ = !scene_.clouds().empty();
  if (auto names = pass_names_of(*method_, scene_, entities_ != nullptr, clouds_may_come_);
      names != recorder_.pass_names())
    recorder_.reset_passes(std::move(names));
}

void FrameRenderer::draw_clouds(const Camera& camera, const gl::RenderTarget& target, ViewResult& r) {
  const auto t0 = Clock::now();
  if (!clouds_) clouds_ = std::make_unique<gl::CloudPass>(shader_dir_);
  gl::CloudView view;
  view.inv_view_proj = glm::inverse(camera.view_projection());
  view.eye_altitude_m = float(camera.position.z);
  view.earth_radius_m = camera.earth_radius_m;
  view.fov_y_deg = camera.fov_y_deg;
  view.fog_k = float(scene_.fog_k());
  view.fog_colour = scene_.sky_light().sky_horizon;
  const auto frame = environment::cloud_frame(scene_.clouds(), camera.position, scene_.time_s(), scene_.sky_light());
  clouds_->draw(frame, view, target, recorder_);
  end_stage();
  r.timings.clouds_ms = ms_since(t0);
}

void FrameRenderer::end_stage() const {
  if (!pipelined_) gl::finish();
}

ViewSelection FrameRenderer::select(const Camera& world_camera, const gl::RenderTarget& target) {
  ViewSelection s;
  s.world_eye = world_camera.position;
  // Methods work in terrain-local metres (world origin subtracted in double)
  // and see the scene's Earth curvature through the camera.
  s.camera = scene_.local_camera(world_camera);
  // The clouds come and go with the host's weather: the pass list changes
  // only when they do (no list is built in a frame that keeps it).
  if (!scene_.clouds().empty() != scene_had_clouds_) update_pass_names();
  recorder_.begin_frame();
  s.work_at_start = gl::work_tally();
  method_->set_viewport(target.width(), target.height());
  s.lod_start = Clock::now();
  s.scene_requests = method_->update(s.camera);
  return s;
}

ViewResult FrameRenderer::draw(const ViewSelection& selection, const gl::RenderTarget& target) {
  const Camera& camera = selection.camera;
  const gl::WorkTally& at_start = selection.work_at_start;
  ViewResult r;
  r.timings.lod_ms = ms_since(selection.lod_start);

  auto t0 = Clock::now();
  if (deferred_) target.use_surface_targets();
  if (water_) target.use_water_marks();
  target.bind();
  // An eye under the surface sees the terrain's undersides: culled only while it is above.
  gl::begin_frame(back_face_culling_ && terrain::back_faces_hidden(scene_.heightfield(), camera.position));
  if (wireframe_) gl::set_wireframe(true);
  recorder_.begin(recorder_.pass_names().front());  // a multi-pass method opens its own as it goes
  r.method = method_->draw(camera, target);
  recorder_.end();
  if (wireframe_) gl::set_wireframe(false);
  const bool drew_terrain = !r.method.passes.empty();  // a sky-only view runs no terrain pass
  if (deferred_ && drew_terrain) {
    scene_.bind_common(deferred_shade_program_, camera, method_->window_set());
    deferred_shade_.run(target, deferred_shade_program_, recorder_, bool(water_));
    if (water_) {
      scene_.bind_common(water_shade_program_, camera, method_->window_set());
      water_->run(target, water_mask_program_, water_shade_program_, recorder_);
    }
  }
  // Entities over the terrain as drawn (depth-tested against it), lit as it.
  if (entities_) r.entities = entities_->draw(camera, selection.world_eye, scene_, target, recorder_);
  end_stage();
  r.timings.terrain_ms = ms_since(t0);

  t0 = Clock::now();
  sky_.draw(glm::inverse(camera.view_projection()), scene_.sky_light(), recorder_);
  end_stage();
  r.timings.sky_ms = ms_since(t0);
  // The clouds blend over the single-sampled picture: a multisampled frame's
  // after its resolve, a post-filtered one's before its filter.
  const bool clouds = !scene_.clouds().empty();
  if (target.samples() > 1) {
    t0 = Clock::now();
    target.resolve();
    end_stage();
    r.timings.resolve_ms = ms_since(t0);
  }
  if (clouds) draw_clouds(camera, target, r);
  if (target.post_pass()) {
    t0 = Clock::now();
    post_filter_.run(target, recorder_);
    end_stage();
    r.timings.resolve_ms = ms_since(t0);
  }
  r.passes = recorder_.read();
  r.total.name = "total";
  for (const auto& p : r.passes) {
    r.total.vs_invocations += p.vs_invocations;
    r.total.fs_invocations += p.fs_invocations;
    r.total.primitives += p.primitives;
    r.total.samples_passed += p.samples_passed;
  }
  // Uploads in the LOD and scene steps (outside every pass) count too.
  r.total.draw_calls = gl::work_tally().draw_calls - at_start.draw_calls;
  r.total.bytes_uploaded = gl::work_tally().bytes_uploaded - at_start.bytes_uploaded;
  if (!r.method.passes.empty()) r.method.passes += "+";
  if (deferred_ && drew_terrain) r.method.passes += water_ ? "shade+water+" : "shade+";
  if (r.entities.in_view > 0) r.method.passes += "entities+";
  r.method.passes += "sky";
  if (clouds) r.method.passes += "+clouds";
  if (target.post_pass()) r.method.passes += "+aa";
  return r;
}

}  // namespace ig::render
