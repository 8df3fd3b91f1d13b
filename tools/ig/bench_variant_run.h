// One method at one knob value flown along the bench's frames: renders a
// frame when asked, times it, compares the sampled frames with the
// reference, and sums it all up as a BenchRow. ig bench flies its variants
// one after the other, or all of them frame by frame in turn (--interleave),
// so that a drift of the machine's speed or of the GPU's clock during the
// run reaches every method alike.
#pragma once

#include <chrono>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "gl/frame_fence.h"
#include "render/camera.h"
#include "render/frame_renderer.h"
#include "render/terrain_method.h"
#include "session/bench_report.h"
#include "session/bench_samples.h"
#include "stats/frame_log.h"
#include "stats/image_error.h"
#include "stats/temporal_error.h"

namespace ig::gl {
class RenderTarget;
}

namespace ig::app {

using Clock = stats::WallClock;

// One method at one knob value to run.
struct Variant {
  std::string method;
  std::optional<double> knob;  // nullopt: the method's default
  bool is_default = true;
};

// What every variant flies and is compared with, shared by all of them.
struct BenchFlight {
  render::TerrainScene* scene = nullptr;
  std::string shader_dir;
  render::MethodOptions method_options;
  std::vector<int> frames;       // scenario frames, in flight order
  std::vector<int> sample_pos;   // positions in `frames` compared with the reference
  std::set<int> before_pos;      // positions rendered just before a sample
  std::map<int, stats::FrameImage> reference;       // by position: the samples
  std::map<int, stats::LumaImage> reference_luma;   // by position: samples and frames before them
  std::map<int, render::Camera> reference_camera;   // by position
  std::function<render::Camera(int frame)> camera_at;
  const gl::RenderTarget* target = nullptr;
  int width = 0, height = 0;
  double time_step_s = 0.0;
  stats::FrameLog* frames_csv = nullptr;
  stats::FrameLog* pipelined_csv = nullptr;  // frames flown pipelined (ig bench --pipelined)
  stats::FrameLog* samples_csv = nullptr;
};

class VariantRun {
 public:
  // Builds the method (timed as the row's build_ms) and its renderer.
  VariantRun(const Variant& variant, const BenchFlight& flight);
  VariantRun(const VariantRun&) = delete;
  VariantRun& operator=(const VariantRun&) = delete;

  const std::string& label() const { return label_; }
  // The first frame once, untimed: first-use allocations stay out of the figures.
  void warm_up();
  // Renders, times and logs the frame at position `pos` of flight.frames.
  // Positions must come in increasing order (temporal pairs and incremental
  // methods rely on it).
  void fly(int pos);
  // Renders the frame at position `pos` pipelined (gl::FrameFence): issued
  // while up to kFramesInFlight - 1 earlier ones are still being drawn, as a
  // live IG with frames in flight runs. Timed, not compared. A run of
  // consecutive positions is one stretch; end_pipelined() drains it.
  static constexpr int kFramesInFlight = 2;
  void fly_pipelined(int pos);
  void end_pipelined();
  // The row of medians and errors; call once, after the last fly().
  session::BenchRow finish();
  // Wall time this variant took so far: its build, warm-up and frames
  // (read-backs and comparisons included), in either flying order.
  double seconds() const { return spent_ms_ / 1000.0; }

 private:
  void render_and_compare(int pos);

  const BenchFlight& flight_;
  Variant variant_;
  session::BenchRow row_;
  double spent_ms_ = 0.0;
  std::unique_ptr<render::TerrainMethod> method_;
  std::unique_ptr<render::FrameRenderer> renderer_;
  std::string label_;
  stats::Cell knob_cell_;
  session::BenchSamples samples_;
  std::vector<double> frame_ms_, cpu_ms_, cores_, hidden_, lod_ms_, triangles_, vs_, fs_, passed_, prims_, draws_,
      uploads_;
  std::map<int, stats::LumaImage> method_before_;  // the method's images of the frames before samples
  // Pipelined frames: issued, not yet seen done (oldest first).
  struct InFlight {
    gl::FrameFence fence;
    Clock::time_point issued;
    int frame = 0;
    double lod_ms = 0.0;
    double interval_ms = -1.0, cpu_ms = -1.0;  // from the frame issued before it in the stretch
  };
  void retire_done(bool wait_oldest);
  std::deque<InFlight> in_flight_;
  std::optional<Clock::time_point> last_issue_;
  double last_issue_cpu_ms_ = 0.0;
  std::vector<double> pipe_interval_ms_, pipe_cpu_ms_, pipe_latency_ms_, pipe_lod_ms_;
  size_t next_sample_ = 0;
  int last_pos_ = -1;
};

// Every knob value of `method`'s sweep (plus its default when the sweep lacks
// it), or its default alone.
std::vector<Variant> variants_for(const std::string& method, bool sweep, const render::MethodOptions& options);

}  // namespace ig::app
