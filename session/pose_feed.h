#pragma once
// Received poses for the frame loop: the intake (decoders, placement,
// counters) and the pose filter for one scene, plus what each frame logs
// about them. Used live (ig serve) and for replays of recordings (ig run
// --recording), so both go through the same code.

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/filter/pose_filter.h"
#include "io/pose.h"
#include "io/pose_intake.h"
#include "stats/frame_log.h"
#include "terrain/heightfield.h"

namespace ig::session {

class PoseFeed {
 public:
  explicit PoseFeed(const terrain::Heightfield& hf, const io::PoseFilterOptions& options = {});
  io::PoseIntake& intake() { return intake_; }
  const io::PoseFilter& filter() const { return filter_; }

  // The pose to render at IG time now_s; `fallback` until the first packet.
  // display_lead_s: expected time from now_s until the frame is complete
  // (the latest mode extrapolates to it).
  io::Pose pose_at(double now_s, const io::Pose& fallback, double display_lead_s = 0.0);
  // The frame just rendered with that pose was complete at complete_s (IG clock):
  // logged as transport delay (newest pose received -> frame complete).
  void frame_complete(double complete_s);
  // pose_age_ms, pose_source, pose_mode, latency_mode, transport_delay_ms,
  // shown_time_s, frame_complete_s, host_frame, packets_ok, packets_bad
  // (this frame's state).
  void append_columns(std::vector<stats::Cell>& row) const;
  nlohmann::json summary() const;
  bool georeferenced() const { return georeferenced_; }
  void set_latency_mode(io::LatencyMode m) { filter_.set_latency_mode(m); }
  double pose_age_ms() const { return last_age_ms_; }  // -1: no pose yet

 private:
  io::PoseFilter filter_;
  io::PoseIntake intake_;
  bool georeferenced_ = false;
  double last_age_ms_ = -1.0;
  std::string last_mode_ = "none";
  double frame_start_s_ = 0.0, complete_s_ = 0.0;
  double shown_time_s_ = 0.0;  // IG-clock instant the pose shows (sender time + offset)
};

}  // namespace ig::session
