#pragma once
// The interface every terrain LOD method implements (reference, two-level,
// and the baselines). A frame is: update() on the CPU (selection / LOD, no
// GL draw calls), then draw() issuing the passes into the bound target.
// Methods never read sockets or files; they see the camera and the scene.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "gl/render_target.h"
#include "gl/work_counters.h"
#include "lod/scene_requests.h"
#include "options/method_options.h"
#include "options/twolevel_options.h"
#include "render/camera.h"
#include "render/terrain_scene.h"

namespace ig::render {

// The one setting of a method that trades image error for run time (its
// "error knob"), e.g. a screen-space tolerance in pixels or a triangle budget.
struct ErrorKnob {
  std::string name;  // e.g. "tau_px", "C1", "level0_budget"
  std::string unit;  // e.g. "px", "", "triangles"
  double value = 0.0;
};

// Knobs a running method may take between frames (Modbus holding registers,
// docs/modbus.md). A field left empty keeps the method's value; a method
// ignores the knobs it has not.
struct MethodTuning {
  // Level1 size thresholds (a1, a2), a1 < a2 (options::TwoLevelOptions).
  std::optional<std::pair<double, double>> level1_thresholds;
};

// A multi-level method's state after the last frame, for the status registers.
struct LevelStatus {
  int level1_size = 0;          // Level1 vertices a side
  double coverage_ratio = -1.0; // Level1's share of the terrain pixels (-1: not measured yet)
};

struct MethodFrameStats {
  long long triangles = 0;  // triangles submitted this frame
  std::string passes;       // which passes ran, e.g. "terrain" or "level1+band+level0"
  // Method-specific per-frame columns, same names and order every frame.
  std::vector<std::pair<std::string, double>> columns;
  // The column of that name, or 0 when the method has none.
  double column(std::string_view name) const {
    for (const auto& [n, v] : columns)
      if (n == name) return v;
    return 0.0;
  }
};

class TerrainMethod {
 public:
  virtual ~TerrainMethod() = default;
  virtual std::string name() const = 0;
  // Names of the method-specific columns (fixed for the run).
  virtual std::vector<std::string> column_names() const = 0;
  // The viewport the next update() selects for; FrameRenderer calls it before
  // every update(). Methods with a screen-space tolerance need its height.
  virtual void set_viewport(int width_px, int height_px) {
    (void)width_px;
    (void)height_px;
  }
  // CPU-side LOD selection for this camera. Returns what the frame needs of
  // the scene (tiles, a window's place; empty for most methods), which the
  // frame's scene step (TerrainScene::apply) carries out before draw().
  virtual lod::SceneRequests update(const Camera& camera) = 0;
  // Draw into the target, which the caller has bound and cleared with
  // reversed-Z depth set up. A method with offscreen passes rebinds it after.
  virtual MethodFrameStats draw(const Camera& camera, const gl::RenderTarget& target) = 0;

  // The knob and its value in use (nullopt: the method has none, e.g. reference).
  virtual std::optional<ErrorKnob> knob() const { return std::nullopt; }
  // The passes draw() runs, in order, for the work counters (fixed for the
  // run). A method with one pass needs nothing: FrameRenderer opens "terrain".
  virtual std::vector<std::string> pass_names() const { return {"terrain"}; }
  // Applies runtime knobs at the frame boundary (default: none to take).
  virtual void tune(const MethodTuning& tuning) { (void)tuning; }
  // The last frame's level state (nullopt: a single-level method).
  virtual std::optional<LevelStatus> level_status() const { return std::nullopt; }
  // The height the last frame drew at DEM sample position (i, j) where the
  // method drew a coarser surface than the DEM; nullopt where it drew full
  // resolution (everywhere, by default).
  virtual std::optional<double> coarse_height_at(double i, double j) const {
    (void)i;
    (void)j;
    return std::nullopt;
  }
  // The scene's window set (TerrainScene::claim_windows) the method's
  // programs read heights and imagery through: the deferred shading pass
  // reads through the same (-1: none).
  virtual int window_set() const { return -1; }
  // FrameRenderer's pass recorder; a method with several passes opens each
  // with begin_pass() (no-op without a recorder).
  void set_pass_recorder(gl::PassRecorder* recorder) { passes_ = recorder; }

  // The method's own bound on the screen-space geometric error of the last
  // update(), in pixels, for this camera and a viewport viewport_height_px
  // tall (nullopt: it claims none). The reference claims 0.
  virtual std::optional<double> error_bound_px(const Camera& camera, int viewport_height_px) const {
    (void)camera;
    (void)viewport_height_px;
    return std::nullopt;
  }

 protected:
  void begin_pass(std::string_view name, bool count_samples = true) {
    if (passes_) passes_->begin(name, count_samples);
  }

 private:
  gl::PassRecorder* passes_ = nullptr;
};

// Pixels per radian at the centre of a viewport viewport_height_px tall: a
// geometric error e metres at distance d projects to at most e / d times this.
double pixels_per_radian(const Camera& camera, int viewport_height_px);

using options::MethodOptions;    // options/method_options.h
using options::TwoLevelOptions;  // options/twolevel_options.h

// Names accepted by make_method().
std::vector<std::string> method_names();
// Throws std::invalid_argument naming the method and the choices. The
// method takes its own struct of `options`; `knob` overrides its error knob
// there (for sweeps); methods without a knob ignore it.
std::unique_ptr<TerrainMethod> make_method(const std::string& name, TerrainScene& scene,
                                           const std::string& shader_dir, const MethodOptions& options,
                                           std::optional<double> knob = std::nullopt);
// The error knob a method built from `options` would report, read from the
// options without building it (nullopt: the method has none). Throws
// std::invalid_argument for an unknown name.
std::optional<ErrorKnob> default_knob(const std::string& name, const MethodOptions& options);
// The knob values `ig bench --sweep` runs for a method, from least to most
// accurate (empty for methods without a knob).
std::vector<double> knob_sweep(const std::string& name);

}  // namespace ig::render
