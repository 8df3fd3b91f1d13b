#pragma once
// A scripted run: which terrain, how to render it, which channels, the
// keyframed ownship path, the simulation time step and when to capture.
// Schema and examples: docs/scenario.md. Parsing is strict: an unknown key or
// a bad value throws ScenarioError naming the key path (e.g. "path.keys[2].t").

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/filter/pose_filter.h"
#include "options/shading_options.h"
#include "options/terrain_options.h"
#include "options/method_options.h"
#include "options/twolevel_options.h"
#include "options/water_options.h"

namespace ig::io {

struct ScenarioError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Parameters of the seeded fractal terrain generator (fBm + ridged noise).

// How a file is read (encoding, scale, offset, spacing_m) comes from
// options::DemLoadOptions, the loader's own settings.
struct TerrainSpec : options::DemLoadOptions {
  // Exactly one of file / generator is set.
  std::optional<std::string> file;  // environment variables already expanded
  std::optional<options::SyntheticTerrainOptions> generator;
  // Samples a side of the full-resolution height window the two-level
  // method reads around Level1 (render/height_window_texture.h); 0 = none.
  int height_window = 0;
  // Largest height-texture side the scene may use (0 = the GL limit); a DEM
  // beyond it is drawn from an overview plus the height window, as beyond
  // the GL limit (tests do that on a small DEM).
  int texture_limit = 0;
  // Paged heights (over memory_budget_mb): false (live, default) keeps
  // Level1 on its last square while the tiles of a new one are read, so no
  // frame waits on I/O; true makes a frame wait for them instead, so a
  // replay's pictures do not depend on disk speed (regression captures).
  bool wait_for_pages = false;
  // Memory budget for imagery beyond the texture limit (paged from GDAL in
  // tiles, terrain/imagery_loader.h; raised to what the imagery window needs).
  int imagery_budget_mb = 512;
  // Where the water is (terrain.water): found in the DEM ("auto"), none
  // ("off"), or the user's water file (water/water_setup.h).
  options::WaterOptions water;
};

struct RenderSpec {
  int width = 640;
  int height = 480;
  double fov_y_deg = 60.0;
  double near_m = 0.5;
  double far_m = 300000.0;
  std::string method = "twolevel";
  // fog_visibility_m, sky_zenith_rgb, sky_horizon_rgb, sun_direction, and
  // the top-level environment.time_utc
  options::ShadingOptions shading;
  std::optional<std::string> imagery;  // optional RGB image draped over the DEM
  double frame_budget_ms = 16.667;     // frames slower than this are counted
  bool vsync = true;                   // windowed only
  // Earth curvature drop (docs/scenario.md): "auto" = on for georeferenced
  // terrain spanning more than 5 km (session::earth_radius_for), "on", "off".
  std::string earth_curvature = "auto";
  options::TwoLevelOptions twolevel;  // render.twolevel
  // render.roam, render.quadtree, render.geomipmap, render.chunked, render.cdlod
  options::RoamOptions roam;
  options::QuadtreeOptions quadtree;
  options::GeoMipMapOptions geomipmap;
  options::ChunkedOptions chunked;
  options::CdlodOptions cdlod;
  // Every method's settings, as make_method takes them.
  options::MethodOptions method_options() const {
    return {twolevel, roam, quadtree, geomipmap, chunked, cdlod};
  }
  // Anti-aliasing of the IG framebuffer: "msaa" (msaa_samples per pixel,
  // clamped to GL_MAX_SAMPLES), "fxaa" (a post-process edge filter), "off",
  // or "auto": msaa on a GPU, fxaa on a CPU rasterizer (llvmpipe), where
  // multisampling costs 2.5-3.5 times the frame (docs/rendering.md).
  std::string antialiasing = "auto";
  int msaa_samples = 4;
};

struct ChannelSpec {
  std::string name = "main";
  double heading_offset_deg = 0.0;
  double pitch_offset_deg = 0.0;
  double roll_offset_deg = 0.0;
  std::optional<double> fov_y_deg;  // overrides render.fov_y_deg
  // Set by a host (CIGI View Control), not by config files: the entity the
  // view rides on (0: the ownship) and the eye's offset from its reference
  // point in its body axes (x forward, y right, z down, metres): chase,
  // tower and wingman views.
  std::uint16_t entity = 0;
  std::array<double, 3> eye_offset_m{0.0, 0.0, 0.0};
};

enum class PositionFrame { Local, Geodetic };
enum class AltitudeMode { AboveSeaLevel, AboveGround };

struct PathKey {
  double t_s = 0.0;
  // Local: x east, y north, z up (m). Geodetic: lat deg, lon deg, alt m.
  std::array<double, 3> position{};
  double heading_deg = 0.0;  // 0 = north, clockwise positive
  double pitch_deg = 0.0;    // nose up positive
  double roll_deg = 0.0;     // right wing down positive
};

struct PathSpec {
  PositionFrame frame = PositionFrame::Local;
  AltitudeMode altitude = AltitudeMode::AboveSeaLevel;
  std::vector<PathKey> keys;  // strictly increasing t_s, at least one
};

// A scripted entity (docs/scenario.md, "entities"): an entity type the model
// table draws, moved along a path like the ownship's. Clamped: the path's
// altitude is the height above the surface under it (water included), kept
// at every frame; conformal also lays it on the surface's slope. With a
// parent, the path gives offsets from that entity in its body axes (x right,
// y forward, z up) and attitudes relative to it.
enum class EntityClamp { None, Ground, Conformal };
struct EntitySpec {
  std::uint16_t id = 1;
  std::uint16_t type = 0;
  PathSpec path;
  EntityClamp clamp = EntityClamp::None;
  std::optional<std::uint16_t> parent;
  double alpha = 1.0;
};

struct Scenario {
  std::string name;
  std::string source_path;  // file it was read from ("" when parsed from text)
  TerrainSpec terrain;
  RenderSpec render;
  std::vector<ChannelSpec> channels;  // at least one
  PathSpec path;
  std::vector<EntitySpec> entities;  // at most kMaxScenarioEntities, ids unique, parents listed
  double time_step_s = 1.0 / 60.0;
  double duration_s = 10.0;             // defaults to the last key's time when omitted
  std::vector<double> capture_times_s;  // captured as PNG (nearest frame)
  // capture.every_s: besides those, a capture every this many seconds of
  // sim time from 0 (0 = none); session::CaptureSchedule serves both.
  double capture_every_s = 0.0;
  // Live IG (ig serve): how the pose filter trades latency for smoothness,
  // "smooth", "latest" or "sync" (docs/pose-filter.md, "Latency modes");
  // ig serve --latency and Modbus override it.
  LatencyMode live_latency = LatencyMode::Smooth;
};

// Parse JSON text / a file. Throws ScenarioError("<where>: <key path>: <reason>").
Scenario parse_scenario(const std::string& json_text, const std::string& origin = "<string>");
Scenario load_scenario(const std::string& path);

// "${VAR}" and "$VAR" expansion; throws ScenarioError naming an unset variable.
std::string expand_env(const std::string& text);

// Number of frames the scenario runs: floor(duration / step + 1e-9) + 1 (the
// epsilon absorbs rounding: 0.3 s at 0.1 s is 4 frames). Frame k is at
// t = k * step. Throws ScenarioError for a step <= 0 or a negative duration.
int scenario_frame_count(const Scenario& s);

}  // namespace ig::io
