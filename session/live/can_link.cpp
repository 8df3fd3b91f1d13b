// ig serve's SocketCAN pose source (built with IG_WITH_CAN; docs/can.md).
#include <iostream>

#include "io/can/can_pose_source.h"
#include "session/live/serve_plugins.h"

namespace ig::session {
namespace {

class CanLink final : public ExtraPoseSource {
 public:
  explicit CanLink(const CanSourceSettings& s) : settings_(s) {
    io::can::CanPoseSourceOptions o;
    o.ifname = s.ifname;
    o.pose.altitude_id = std::uint16_t(s.altitude_id);
    o.pose.max_age_s = s.max_age_ms * 1e-3;
    if (s.node) o.decode.node_id = std::uint8_t(*s.node);
    can_ = std::make_unique<io::can::CanPoseSource>(o);
  }

  void poll(PoseFeed& feed) override {
    can_->poll([&](const io::wire::PoseMessage& m, double t, io::can::CanFormat fmt) {
      feed.intake().handle_pose(fmt == io::can::CanFormat::CanFd ? io::Protocol::CanFd : io::Protocol::CanAerospace,
                                m, t);
    });
    // Say each change of the interface's state once; rendering goes on with
    // the last good pose (the filter holds / extrapolates it).
    if (can_->socket().state_changes() != state_) {
      state_ = can_->socket().state_changes();
      const auto& err = can_->socket().last_error();
      if (!err.empty())
        std::cerr << "ig serve: CAN " << err << "; retrying every 0.5 s, rendering the last good pose\n";
      else if (!settings_.quiet)
        std::cerr << "ig serve: CAN " << settings_.ifname << ": receiving\n";
    }
  }

  ExtraSourceStatus status() const override {
    ExtraSourceStatus s;
    s.link = can_->socket().is_open() ? 1 : 2;
    s.poses = std::uint32_t(can_->poses());
    s.rejected =
        std::uint32_t(can_->canaerospace_stats().rejected() + can_->fd_stats().frames - can_->fd_stats().accepted);
    s.error_frames = std::uint32_t(can_->socket().stats().error_frames);
    return s;
  }

  std::string summary_key() const override { return "can"; }
  nlohmann::json summary() const override { return can_->summary(); }

 private:
  CanSourceSettings settings_;
  std::unique_ptr<io::can::CanPoseSource> can_;
  std::uint64_t state_ = 0;
};

}  // namespace

std::unique_ptr<ExtraPoseSource> make_can_source(const CanSourceSettings& settings) {
  return std::make_unique<CanLink>(settings);
}

}  // namespace ig::session
