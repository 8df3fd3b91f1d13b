#include "pose_feed.h"

#include "scene_setup.h"

namespace ig::app {

PoseFeed::PoseFeed(const terrain::Heightfield& hf, const io::PoseFilterOptions& options)
    : filter_(options), intake_(filter_, geodetic_placer(hf)), georeferenced_(hf.georef.has_value()) {}

io::Pose PoseFeed::pose_at(double now_s, const io::Pose& fallback) {
  const auto f = filter_.sample(now_s);
  if (!f) {
    last_age_ms_ = -1.0;
    last_mode_ = "none";
    return fallback;
  }
  last_age_ms_ = f->age_s * 1000.0;
  last_mode_ = f->mode == io::FilteredPose::Interpolating   ? "interpolating"
               : f->mode == io::FilteredPose::Extrapolating ? "extrapolating"
                                                            : "holding";
  return io::Pose{f->position, f->attitude};
}

void PoseFeed::append_columns(std::vector<stats::Cell>& row) const {
  const std::string source = intake_.last_source();
  row.emplace_back("pose_age_ms", last_age_ms_);
  row.emplace_back("pose_source", source.empty() ? std::string("none") : source);
  row.emplace_back("pose_mode", last_mode_);
  row.emplace_back("packets_ok", static_cast<long long>(intake_.total_ok()));
  row.emplace_back("packets_bad", static_cast<long long>(intake_.total_bad()));
}

nlohmann::json PoseFeed::summary() const {
  nlohmann::json sources = nlohmann::json::object();
  for (int p = 0; p < io::kProtocolCount; ++p) {
    const auto& c = intake_.counters(io::Protocol(p));
    if (c.ok + c.bad + c.no_pose == 0) continue;
    sources[io::protocol_name(io::Protocol(p))] = {
        {"ok", c.ok}, {"bad", c.bad}, {"no_pose", c.no_pose}, {"reasons", c.reasons}};
  }
  const auto& f = filter_.counters();
  return {{"sources", sources},
          {"filter",
           {{"received", f.received},
            {"accepted", f.accepted},
            {"duplicates", f.duplicates},
            {"out_of_order", f.out_of_order},
            {"late_inserted", f.late_inserted},
            {"non_finite", f.non_finite},
            {"time_jumps", f.time_jumps},
            {"extrapolations", f.extrapolations},
            {"holds", f.holds}}},
          {"georeferenced", georeferenced_}};
}

}  // namespace ig::app
