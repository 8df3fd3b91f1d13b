#pragma once
// Replays a scenario frame by frame: the IG's data flow in one place,
//   scripted pose -> camera(s) -> LOD update -> passes -> capture -> frame log.
// ig run drives it to the end and writes the outputs; tests drive it frame by
// frame and look at the pixels.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "environment/sun_tracker.h"
#include "environment/terrain_geolocation.h"
#include "gl/gl_context.h"
#include "gl/render_target.h"
#include "io/path_interpolator.h"
#include "io/scenario.h"
#include "render/frame_renderer.h"
#include "session/scenario_entities.h"
#include "render/terrain_method.h"
#include "render/terrain_scene.h"
#include "stats/frame_log.h"
#include "terrain/heightfield.h"

namespace ig::session {

struct RunOptions {
  std::optional<int> frames;          // overrides the scenario's duration
  std::optional<int> width, height;   // overrides render size
  std::optional<std::string> method;  // overrides render.method
  bool headless = true;
  bool fullscreen = false;
  std::optional<bool> vsync;
  std::string shader_dir;             // "" = gl::default_shader_dir()
  bool pass_times = false;            // log every pass's own wall time (render::FrameRenderer::set_pass_times)
};

// One view of the scene. LOD state (the two-level size controller, the
// look-at point) depends on the view, so each channel has its own method.
struct ChannelView {
  io::ChannelSpec spec;
  render::Camera camera;
  std::unique_ptr<gl::RenderTarget> target;
  std::unique_ptr<render::TerrainMethod> method;
  std::unique_ptr<render::FrameRenderer> renderer;
  render::ViewResult last;
  double render_ms = 0.0;  // LOD update + passes of the last frame
};

struct FrameResult {
  int frame = 0;
  double sim_time_s = 0.0;
  io::Pose pose;
  double pose_ms = 0.0;
  // Paged heights only (-1 otherwise): tiles this frame had to
  // wait for (synchronous page-ins: height window, ray casts, queries) and
  // tiles the background thread loaded during it.
  long long page_waits = -1;
  long long page_ins = 0;
  // Paged imagery only (-1 otherwise): imagery window moves held because a
  // tile was not resident, the tiles they missed, tiles the imagery cache's
  // background thread loaded, and tiles a frame waited for (0 by design).
  long long imagery_held = -1;
  long long imagery_missing = 0, imagery_page_ins = 0, imagery_page_waits = 0;
  double visibility_m = 0.0;  // the fog's visibility this frame (0: no fog)
};

// render.antialiasing with "auto" decided for a GL renderer: multisampling
// on a GPU, the post filter on a CPU rasterizer (llvmpipe, softpipe).
std::string resolve_antialiasing(const std::string& setting, const std::string& gl_renderer);
// A channel's frame target as render.antialiasing asks (multisampled,
// post-filtered or plain; "auto" resolved first).
std::unique_ptr<gl::RenderTarget> make_frame_target(const io::RenderSpec& render, int width, int height);

// The frame's work counters as log columns: totals (vs_invocations,
// fs_invocations, primitives, draw_calls, upload_bytes), then with per_pass
// <pass>_vs, <pass>_fs, <pass>_prims, <pass>_draws, <pass>_passed (samples
// that passed the depth test) for every pass, and <pass>_pass_ms when the passes
// were timed.
void append_work_columns(std::vector<stats::Cell>& row, const render::ViewResult& view, bool per_pass);

// One frames.csv row for a channel; wall_ms = pose + render + readback + present.
std::vector<stats::Cell> frame_log_row(const FrameResult& frame, const ChannelView& channel,
                                       double readback_ms, double present_ms);

class ScenarioRunner {
 public:
  // Loads the terrain, creates its own GL context and every GPU resource.
  // Throws with a one-line reason (bad file, no GL 4.5, unknown method...).
  // Several runners may live on one thread: each makes its own context
  // current when it renders, rebuilds, presents or is destroyed, so read a
  // runner's targets after its own render, before another runner's.
  ScenarioRunner(io::Scenario scenario, const RunOptions& options);
  ~ScenarioRunner();
  ScenarioRunner(const ScenarioRunner&) = delete;
  ScenarioRunner& operator=(const ScenarioRunner&) = delete;

  const io::Scenario& scenario() const { return scenario_; }
  const terrain::Heightfield& heightfield() const { return heightfield_; }
  const gl::GlContext& context() const { return *context_; }
  const std::string& shader_dir() const { return options_.shader_dir; }
  // The first channel's method (tests and benchmarks look at its state).
  render::TerrainMethod& method() { return *channels_.front().method; }
  int frame_count() const { return frame_count_; }
  double load_ms() const { return load_ms_; }
  std::vector<ChannelView>& channels() { return channels_; }
  // The shared terrain scene (shading parameters, e.g. fog, set at run time).
  render::TerrainScene& scene() { return *scene_; }
  // The sun of the last frame (before the first: at the first pose):
  // elevation and azimuth clockwise from true north. With
  // environment.time_utc it follows the clock and the eye's place; otherwise
  // it is render.sun_direction (or the default sun) as angles.
  const environment::SunAngles& sun() const { return sun_; }
  // The host's clock (CIGI Celestial Sphere Control): UTC `time` at sim time
  // `at_s`; from the next frame the sun follows it, advancing with sim time
  // when `runs`, held at `time` otherwise. False (nothing changes) where the
  // terrain has no georeference to place the sun.
  bool set_time_of_day(const options::UtcDateTime& time, double at_s, bool runs);
  // The clock's time when last set (nullopt: no clock; the sun is a fixed direction).
  const std::optional<options::UtcDateTime>& clock_start() const { return clock_start_; }

  // Renders frame k (sim time k * step, pose from the scenario's path) for
  // every channel into its target.
  FrameResult render_frame(int k);
  // Renders frame k at sim_time_s with a pose from elsewhere (live intake,
  // a recording); pose_ms is what obtaining it cost.
  FrameResult render_pose(int k, double sim_time_s, const io::Pose& pose, double pose_ms = 0.0);
  // Paged heights with a height window: loads the window around the first
  // pose (the constructor calls it; a front end that places the first pose
  // itself may call it again).
  void prefetch_first_window();
  // Pose at simulation time t (terrain-local, metres above sea level).
  io::Pose pose_at(double t_s) const;
  void present();
  // Rebuilds every channel's LOD method with new two-level settings (Level0
  // budget, band factor, ...) at a frame boundary: Level0 is built again, so
  // that frame takes the build time (docs/results.md).
  void rebuild_method(const options::TwoLevelOptions& twolevel);
  // Windowed: the user closed the window (polls events). Headless: false.
  bool window_closed() { return context_->should_close(); }
  // The host's entities the next frames draw besides the scenario's (the
  // poses' world frame), until set again. The entity renderer and its models
  // are made with the first frame that has an entity: a run without entities
  // has none.
  void set_entities(std::vector<render::EntityInstance> entities);
  render::EntityRenderer* entity_renderer() { return entities_.get(); }
  // Where entity `id` is this frame, for views riding on it (CIGI View
  // Control's entity); unset or nullopt: the view stays on the ownship.
  using EntityPoseLookup = std::function<std::optional<io::Pose>(std::uint16_t id)>;
  void set_entity_lookup(EntityPoseLookup f) { entity_lookup_ = std::move(f); }
  // The camera render_frame / render_pose use for a pose on a channel
  // (ig bench renders other methods with exactly these cameras).
  render::Camera camera_for(const io::Pose& pose, const ChannelView& channel) const;

 private:

  io::Scenario scenario_;
  RunOptions options_;
  terrain::Heightfield heightfield_;
  double load_ms_ = 0.0;
  std::unique_ptr<io::PathInterpolator> path_;
  std::unique_ptr<gl::GlContext> context_;
  std::unique_ptr<render::TerrainScene> scene_;
  std::vector<ChannelView> channels_;
  std::unique_ptr<render::EntityRenderer> entities_;  // GL objects: before context_ in destruction
  std::unique_ptr<ScenarioEntities> scripted_;         // the scenario's entities (none: null)
  std::vector<render::EntityInstance> host_entities_;  // set_entities
  EntityPoseLookup entity_lookup_;
  void draw_entities(std::vector<render::EntityInstance> entities);
  int frame_count_ = 0;
  // Where the eye is on the Earth (null without a georeference).
  std::unique_ptr<environment::TerrainGeolocation> geolocation_;
  std::optional<environment::SunTracker> sun_tracker_;  // with environment.time_utc only
  std::optional<options::UtcDateTime> clock_start_;      // the tracker's time at clock_zero_s_
  double clock_zero_s_ = 0.0;                            // sim time of clock_start_
  bool clock_runs_ = true;
  environment::SunAngles sun_;
  // Moves the scene's sun to sim time t at the eye (environment.time_utc),
  // or, without a time, only works out its angles.
  void update_sun(double sim_time_s, const glm::dvec3& eye);
};

}  // namespace ig::session
