#include "io/can/can_pose_source.h"

#include "io/net/udp_socket.h"

namespace ig::io::can {

CanPoseSource::CanPoseSource(CanPoseSourceOptions options)
    : options_(std::move(options)), socket_(options_.ifname, options_.retry_s), assembler_(options_.pose) {}

int CanPoseSource::handle_frame(const wire::CanFrame& frame, double t_s, const PoseSink& sink) {
  last_frame_t_ = t_s;
  if (frame.id == wire::kCanFdPoseId && !frame.is_extended()) {
    ++fd_.frames;
    const wire::DecodeResult r = wire::decode_can_fd_pose(frame);
    if (!r.pose) {
      ++fd_.rejects[r.reject ? wire::reject_name(*r.reject) : "unknown"];
      return 0;
    }
    ++fd_.accepted;
    ++poses_;
    last_pose_t_ = t_s;
    sink(*r.pose, t_s, CanFormat::CanFd);
    return 1;
  }
  const auto v = wire::decode_canaerospace(frame, canas_, options_.decode);
  if (!v) return 0;
  assembler_.feed(*v, t_s);
  // One pose per sender cycle: when every required field has a new value.
  const std::uint32_t required = assembler_.required_fields();
  if ((assembler_.updated_fields() & required) != required) return 0;
  assembler_.clear_updated();
  const auto pose = assembler_.pose(t_s, last_stale_);
  if (!pose) {
    ++stale_cycles_;
    return 0;
  }
  ++poses_;
  last_pose_t_ = t_s;
  sink(*pose, t_s, CanFormat::CanAerospace);
  return 1;
}

int CanPoseSource::poll(const PoseSink& sink) {
  int poses = 0;
  socket_.poll([&](const wire::CanFrame& f, double t) { poses += handle_frame(f, t, sink); });
  // Nothing complete for longer than the field age limit: refresh the report
  // of which fields are stale or missing (the pose itself is not used).
  const double now = net::steady_now_s();
  if (poses == 0 && now - last_pose_t_ > options_.pose.max_age_s && last_frame_t_ > -1e299) {
    wire::StaleFields s;
    if (!assembler_.pose(now, s)) last_stale_ = s;
  }
  return poses;
}

nlohmann::json CanPoseSource::summary() const {
  const auto& s = socket_.stats();
  const auto& c = canas_;
  const auto& a = assembler_.stats();
  nlohmann::json stale_fields = nlohmann::json::array(), missing_fields = nlohmann::json::array();
  for (int i = 0; i < wire::can_field::kCount; ++i) {
    const std::uint32_t bit = 1u << i;
    if (last_stale_.stale & bit) stale_fields.push_back(wire::can_field_name(bit));
    if (last_stale_.missing & bit) missing_fields.push_back(wire::can_field_name(bit));
  }
  return {
      {"interface", options_.ifname},
      {"open", socket_.is_open()},
      {"last_error", socket_.last_error()},
      {"socket",
       {{"frames", s.frames}, {"fd_frames", s.fd_frames}, {"error_frames", s.error_frames}, {"bus_off", s.bus_off},
        {"kernel_drops", s.kernel_drops}, {"opens", s.opens}, {"open_failures", s.open_failures},
        {"link_errors", s.link_errors}}},
      {"canaerospace",
       {{"frames", c.frames}, {"accepted", c.accepted}, {"not_classic", c.not_classic}, {"unknown_id", c.unknown_id},
        {"wrong_dlc", c.wrong_dlc}, {"wrong_node", c.wrong_node}, {"wrong_type", c.wrong_type},
        {"non_finite", c.non_finite}, {"code_gaps", c.code_gaps}}},
      {"assembler",
       {{"used", a.used}, {"unused_id", a.unused_id}, {"orphan_low", a.orphan_low}, {"orphan_high", a.orphan_high},
        {"half_mismatch", a.half_mismatch}, {"non_finite", a.non_finite}, {"out_of_range", a.out_of_range},
        {"stale_cycles", stale_cycles_}, {"stale_fields", stale_fields}, {"missing_fields", missing_fields}}},
      {"canfd", {{"frames", fd_.frames}, {"accepted", fd_.accepted}, {"rejects", fd_.rejects}}},
      {"poses", poses_},
  };
}

}  // namespace ig::io::can
