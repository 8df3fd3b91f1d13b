#include "session/pose_feed.h"

#include "session/scene_setup.h"

namespace ig::session {

PoseFeed::PoseFeed(const terrain::Heightfield& hf, const io::PoseFilterOptions& options)
    : filter_(options),
      intake_(filter_, geodetic_placer(hf)),
      georeferenced_(hf.georef.has_value()) {}

io::Pose PoseFeed::pose_at(double now_s, const io::Pose& fallback, double display_lead_s) {
  frame_start_s_ = complete_s_ = now_s;
  const auto f = filter_.sample(now_s, display_lead_s);
  if (!f) {
    last_age_ms_ = -1.0;
    last_mode_ = "none";
    return fallback;
  }
  last_age_ms_ = f->age_s * 1000.0;
  shown_time_s_ = f->render_time_s;
  last_mode_ = f->mode == io::FilteredPose::Interpolating   ? "interpolating"
               : f->mode == io::FilteredPose::Extrapolating ? "extrapolating"
                                                            : "holding";
  return io::Pose{f->position, f->attitude};
}

void PoseFeed::frame_complete(double complete_s) { complete_s_ = complete_s; }

void PoseFeed::append_columns(std::vector<stats::Cell>& row) const {
  const std::string source = intake_.last_source();
  const bool have = last_age_ms_ >= 0.0;
  row.emplace_back("pose_age_ms", last_age_ms_);
  row.emplace_back("pose_source", source.empty() ? std::string("none") : source);
  row.emplace_back("pose_mode", last_mode_);
  row.emplace_back("latency_mode", std::string(io::latency_mode_name(filter_.latency_mode())));
  // Newest pose used: received -> the frame showing it complete.
  row.emplace_back("transport_delay_ms", have ? last_age_ms_ + (complete_s_ - frame_start_s_) * 1000.0 : -1.0);
  row.emplace_back("shown_time_s", have ? shown_time_s_ : -1.0);
  row.emplace_back("frame_complete_s", complete_s_);
  const auto hf = intake_.last_host_frame();
  row.emplace_back("host_frame", hf ? static_cast<long long>(*hf) : -1LL);
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
            {"holds", f.holds},
            {"clamped_rates", f.clamped_rates},
            {"clamped_extrapolations", f.clamped_extrapolations},
            {"latency_mode", io::latency_mode_name(filter_.latency_mode())},
            {"playout_delay_ms", filter_.playout_delay_s() * 1e3},
            {"packet_interval_ms", filter_.packet_interval_s() * 1e3},
            {"jitter_ms", filter_.jitter_s() * 1e3}}},
          {"sender_clock",
           {{"stamped", filter_.sender_clock().counters().stamped},
            {"period_ms", filter_.sender_clock().period_s() * 1e3},
            {"relocks", filter_.sender_clock().counters().relocks},
            {"rephases", filter_.sender_clock().counters().rephases},
            {"spread", filter_.sender_clock().counters().spread},
            {"pulled_earlier", filter_.sender_clock().counters().pulled_earlier}}},
          {"georeferenced", georeferenced_}};
}

}  // namespace ig::session
