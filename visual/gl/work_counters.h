#pragma once
// Hardware-independent work per frame, so timings taken on llvmpipe mean
// something on a GPU too: shader invocations and primitives per pass from
// pipeline statistics queries (GL 4.6 / GL_ARB_pipeline_statistics_query),
// plus draw calls and bytes uploaded, tallied where the GL calls are made.

#include <epoxy/gl.h>

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "gl/gl_objects.h"
#include "stats/timing.h"

namespace ig::gl {

// Draw calls and bytes uploaded by GL calls made on this thread (every draw
// and per-frame upload site calls count_draw / count_upload).
struct WorkTally {
  std::uint64_t draw_calls = 0;
  std::uint64_t bytes_uploaded = 0;
};
WorkTally& work_tally();
inline void count_draw() { ++work_tally().draw_calls; }
inline void count_upload(std::uint64_t bytes) { work_tally().bytes_uploaded += bytes; }

struct PassWork {
  std::string name;
  std::uint64_t vs_invocations = 0;
  std::uint64_t fs_invocations = 0;
  std::uint64_t primitives = 0;  // primitives submitted by the pass's draws
  // Samples that passed the depth test (an occlusion query): the fragments
  // an early-z GPU shades in a pass without discard. llvmpipe's
  // fs_invocations count every rasterized fragment, also those the early
  // depth test then rejects, so they measure coverage, not shading.
  std::uint64_t samples_passed = 0;
  std::uint64_t draw_calls = 0;
  std::uint64_t bytes_uploaded = 0;
  // Wall milliseconds from the work before the pass being done to the pass
  // being done, with pass timing on (PassRecorder::set_timed); -1 with it off.
  double ms = -1.0;
};

// Pipeline statistics around consecutive passes of a frame. The passes are
// named up front (a fixed set for the run, so logs have fixed columns);
// begin() ends the active pass, so passes never nest and a pass may run in
// several stretches (their counts add up). Results are read after the
// frame's glFinish, so reading never stalls the pipeline.
class PassRecorder {
 public:
  explicit PassRecorder(std::vector<std::string> pass_names);
  PassRecorder(const PassRecorder&) = delete;
  PassRecorder& operator=(const PassRecorder&) = delete;

  // The context offers pipeline statistics (else invocations and primitives read 0).
  static bool supported();

  void begin_frame();
  // Throws std::logic_error for a name not given at construction. A pass that
  // runs its own samples-passed queries opens with count_samples false (GL
  // allows one active query per target); its samples_passed then reads 0.
  void begin(std::string_view pass, bool count_samples = true);
  void end();
  // Per pass, in construction order (passes that did not run read 0).
  std::vector<PassWork> read();
  const std::vector<std::string>& pass_names() const { return names_; }
  // Pass timing: glFinish before and after every pass, so each pass's wall
  // time is its own work alone (GL timer queries do not time passes on
  // llvmpipe). The waits serialise the frame, which then takes longer.
  void set_timed(bool on) { timed_ = on; }
  // Pipeline statistics and samples-passed queries on (the default) or off:
  // reading them waits for the frame, which frames in flight must not do
  // (draw calls and uploads are still tallied). Between frames only.
  void set_queries(bool on) { queries_ = on; }
  // Another set of passes (the renderer's method changed).
  void reset_passes(std::vector<std::string> pass_names) {
    if (active_) end();
    names_ = std::move(pass_names);
    used_ = 0;
  }

 private:
  struct Segment {
    int pass = 0;
    bool count_samples = true;
    bool queried = false;  // its queries ran
    std::array<Query, 4> queries;  // vertex and fragment invocations, primitives, samples passed
    WorkTally tally_at_begin, tally_at_end;
    stats::WallClock::time_point start;
    double ms = 0.0;  // timed passes only
  };
  std::vector<std::string> names_;
  std::vector<Segment> segments_;  // grows to the most stretches a frame used; reused
  int used_ = 0;
  bool active_ = false;
  bool supported_ = false;
  bool timed_ = false;
  bool queries_ = true;
};

}  // namespace ig::gl
