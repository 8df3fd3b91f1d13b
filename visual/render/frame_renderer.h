#pragma once
// One view of one frame, in two halves: select() runs the method's LOD step
// and returns what it asks of the scene (prefetches, the height window's
// move); the scene's owner carries that out (session/view_step.h) and then
// draw() runs the method's terrain passes, the sky into whatever the terrain
// left uncovered, the cloud layers over both (scenes with clouds), and the anti-aliasing resolve (multisampled) or post pass
// (post-filtered). With deferred shading the terrain passes store each
// pixel's surface and one pass shades them after the method's passes, and in
// a scene with water one more blends the water over them (both part of the
// terrain stage). The renderer itself never changes the scene. Each stage is timed on the wall clock and closed with gl::finish (GL timer queries are not real GPU
// times on llvmpipe), so per-stage figures are honest if slightly pessimistic.

#include <chrono>
#include <memory>

#include "gl/cloud_pass.h"
#include "gl/deferred_shade_pass.h"
#include "gl/post_filter_pass.h"
#include "gl/render_target.h"
#include "gl/sky_pass.h"
#include "gl/water_pass.h"
#include "gl/work_counters.h"
#include "render/camera.h"
#include "render/entity_renderer.h"
#include "render/terrain_method.h"
#include "render/terrain_scene.h"

namespace ig::render {

struct ViewTimings {
  double lod_ms = 0.0;
  double terrain_ms = 0.0;
  double sky_ms = 0.0;
  double clouds_ms = 0.0;   // the cloud layers (0 in a scene without clouds)
  double resolve_ms = 0.0;  // anti-aliasing: averaging the samples, or the edge filter (0 otherwise)
};

struct ViewResult {
  MethodFrameStats method;
  EntityDrawStats entities;
  ViewTimings timings;
  // Work of this frame: per pass (the method's passes, then "sky") and in all.
  std::vector<gl::PassWork> passes;
  gl::PassWork total;
};

// The first half of a frame: the method's selection in terrain-local metres
// and the scene step it asks for. Time until draw() counts as LOD time, so
// the scene step is timed with the selection.
struct ViewSelection {
  Camera camera;  // terrain-local
  glm::dvec3 world_eye{0.0};  // the camera's world position (entities are placed in that frame)
  lod::SceneRequests scene_requests;
  std::chrono::steady_clock::time_point lod_start;
  gl::WorkTally work_at_start;  // the scene step's uploads count in the frame's work
};

class FrameRenderer {
 public:
  // Draws as the scene's shading settings are now (deferred or not, and
  // the stages of its deferred shading pass), which must be those `method`
  // was made with: make both under the same settings.
  FrameRenderer(const TerrainScene& scene, TerrainMethod& method, const std::string& shader_dir);
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;
  ViewSelection select(const Camera& world_camera, const gl::RenderTarget& target);
  ViewResult draw(const ViewSelection& selection, const gl::RenderTarget& target);
  // Terrain drawn as lines instead of filled; the sky stays filled.
  void set_wireframe(bool on) { wireframe_ = on; }
  bool wireframe() const { return wireframe_; }
  // Back-face culling while the eye is above the terrain (terrain/back_faces_hidden.h;
  // the picture is the same, hidden faces cost no fragment work). On by default;
  // off draws every face, as for an eye under the surface.
  void set_back_face_culling(bool on) { back_face_culling_ = on; }
  // Each pass's own wall time in ViewResult::passes (gl::PassRecorder::set_timed):
  // a diagnostic that finishes the GL work around every pass, so frames take longer.
  void set_pass_times(bool on) { recorder_.set_timed(on); }
  // Pipelined frames: no stage waits for the GL (each stage's time is then
  // the time to issue it) and no pipeline statistics are read, so the
  // caller can issue the next frame while this one is drawn (gl::FrameFence).
  // Off by default: every stage finished and timed.
  void set_pipelined(bool on) {
    pipelined_ = on;
    recorder_.set_queries(!on);
  }
  // Draw with another method from the next frame on (a rebuild at a frame
  // boundary): the sky program and the rest are kept, not recompiled; the
  // shading settings are taken again, as the constructor takes them.
  void set_method(TerrainMethod& method);
  // Entities drawn after the terrain, before the sky (nullptr: none; the
  // frame then has no entity pass). Not owned.
  void set_entities(EntityRenderer* entities);
  // Clouds may come during the run (a CIGI host's Weather Control): the
  // work counters carry a "clouds" pass from the first frame (0 while there
  // are none), so a frame log's columns stay the same. Without it the pass
  // is declared only while the scene has clouds.
  void set_clouds_may_come(bool on) {
    clouds_may_come_ = on;
    update_pass_names();
  }
  // For tests: the post filter on every pixel in one draw instead of on the
  // pixels its first draw marks (gl::PostFilterPass).
  void set_post_filter_mask(bool on) { post_filter_.set_edge_mask(on); }

 private:
  const TerrainScene& scene_;
  TerrainMethod* method_;
  std::string shader_dir_;
  gl::SkyPass sky_;
  // Deferred shading (scene.deferred_shading() when the method was set).
  bool deferred_ = false;
  gl::DeferredShadePass deferred_shade_;
  gl::ShaderProgram deferred_shade_program_;
  std::vector<std::string> deferred_shade_stages_;  // what the program was linked from
  // Deferred shading's water pass: only for a scene with water.
  std::unique_ptr<gl::WaterPass> water_;
  gl::ShaderProgram water_mask_program_, water_shade_program_;
  std::vector<std::string> water_stages_;  // what the two programs were linked from
  void take_shading_settings();
  // Made for the first frame with clouds: until then nothing of them exists.
  std::unique_ptr<gl::CloudPass> clouds_;
  void draw_clouds(const Camera& camera, const gl::RenderTarget& target, ViewResult& r);
  void update_pass_names();
  gl::PostFilterPass post_filter_;  // for post-filtered targets (gl::RenderTarget::post_pass)
  gl::PassRecorder recorder_;
  EntityRenderer* entities_ = nullptr;
  bool wireframe_ = false;
  bool back_face_culling_ = true;
  bool clouds_may_come_ = false;
  bool pipelined_ = false;
  void end_stage() const;  // gl::finish unless pipelined
  bool scene_had_clouds_ = false;  // when the pass list was last made
};

}  // namespace ig::render
