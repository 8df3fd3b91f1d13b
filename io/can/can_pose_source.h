#pragma once
// The CAN pose source behind `ig serve --can IFNAME`: reads a SocketCAN
// interface and turns its frames into poses. Two formats share the bus:
// CANaerospace parameters (one value per classic frame, assembled into a pose
// once every required field has a new value) and the project's single-frame
// CAN FD pose (id 0x7E0). Every frame that is not used is counted by reason;
// a pose is never formed from stale fields (docs/can.md).

#include <cstdint>
#include <functional>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "io/can/can_socket.h"
#include "io/wire/can_fd_pose.h"
#include "io/wire/canaerospace.h"

namespace ig::io::can {

enum class CanFormat : std::uint8_t { CanAerospace, CanFd };

struct CanPoseSourceOptions {
  std::string ifname;
  wire::CanPoseConfig pose;          // altitude id, max field age, require_position
  wire::CanAerospaceOptions decode;  // node id filter
  double retry_s = 0.5;              // reopen interval while the interface is unusable
};

struct CanFdStats {
  std::uint64_t frames = 0;    // frames on the FD pose id
  std::uint64_t accepted = 0;
  std::map<std::string, std::uint64_t> rejects;  // reject name -> count
};

class CanPoseSource {
 public:
  using PoseSink = std::function<void(const wire::PoseMessage& pose, double receive_time_s, CanFormat format)>;

  explicit CanPoseSource(CanPoseSourceOptions options);

  // Drains the socket without blocking (reopening it when due) and hands
  // every complete pose to sink. Returns the number of poses delivered.
  int poll(const PoseSink& sink);
  // One frame received at t_s (what poll does per frame; also used by the
  // benchmark and tests to drive the decoders without a kernel).
  int handle_frame(const wire::CanFrame& frame, double t_s, const PoseSink& sink);

  const CanSocket& socket() const { return socket_; }
  const wire::CanAerospaceStats& canaerospace_stats() const { return canas_; }
  const wire::CanPoseAssemblerStats& assembler_stats() const { return assembler_.stats(); }
  const CanFdStats& fd_stats() const { return fd_; }
  // What kept the last attempt from forming a pose (stale / missing fields).
  const wire::StaleFields& last_stale() const { return last_stale_; }
  // Cycles whose required fields were all updated but some were too old.
  std::uint64_t stale_cycles() const { return stale_cycles_; }
  std::uint64_t poses() const { return poses_; }

  // Counters and the socket state for summary.json / Modbus.
  nlohmann::json summary() const;

 private:
  CanPoseSourceOptions options_;
  CanSocket socket_;
  wire::CanAerospaceStats canas_;
  wire::CanPoseAssembler assembler_;
  CanFdStats fd_;
  wire::StaleFields last_stale_;
  std::uint64_t stale_cycles_ = 0;
  std::uint64_t poses_ = 0;
  double last_pose_t_ = -1e300;
  double last_frame_t_ = -1e300;
};

}  // namespace ig::io::can
