#pragma once
// Received poses for the frame loop: the intake (decoders, placement,
// counters) and the pose filter for one scene, plus what each frame logs
// about them. Used live (ig serve) and for replays of recordings (ig run
// --recording), so both go through the same code.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/filter/pose_filter.h"
#include "io/pose.h"
#include "io/pose_intake.h"
#include "stats/frame_log.h"
#include "terrain/heightfield.h"

namespace ig::app {

class PoseFeed {
 public:
  explicit PoseFeed(const terrain::Heightfield& hf, const io::PoseFilterOptions& options = {});
  io::PoseIntake& intake() { return intake_; }
  const io::PoseFilter& filter() const { return filter_; }

  // The pose to render at IG time now_s; `fallback` until the first packet.
  io::Pose pose_at(double now_s, const io::Pose& fallback);
  // pose_age_ms, pose_source, pose_mode, packets_ok, packets_bad (this frame's state).
  void append_columns(std::vector<stats::Cell>& row) const;
  nlohmann::json summary() const;
  bool georeferenced() const { return georeferenced_; }

 private:
  io::PoseFilter filter_;
  io::PoseIntake intake_;
  bool georeferenced_ = false;
  double last_age_ms_ = -1.0;
  std::string last_mode_ = "none";
};

}  // namespace ig::app
