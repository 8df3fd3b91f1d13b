#pragma once
// SocketCAN raw socket on one interface (Linux): classic and CAN FD frames,
// non-blocking reads, error frames and kernel queue drops counted. The
// interface may be missing, down or removed at any time: the socket then
// closes, says why once, and reopens by name every retry interval, so the
// caller (the IG's frame loop) never blocks or throws.

#include <cstdint>
#include <functional>
#include <string>

#include "io/wire/can_frame.h"

namespace ig::io::can {

struct CanSocketStats {
  std::uint64_t frames = 0;        // data frames read (classic + FD)
  std::uint64_t fd_frames = 0;     // of which CAN FD
  std::uint64_t error_frames = 0;  // frames with CAN_ERR_FLAG (controller / bus errors)
  std::uint64_t bus_off = 0;       // error frames reporting bus-off
  std::uint64_t kernel_drops = 0;  // frames the kernel dropped because our queue was full
  std::uint64_t opens = 0;         // successful (re)opens
  std::uint64_t open_failures = 0; // open attempts that failed (no AF_CAN, no such interface, down)
  std::uint64_t link_errors = 0;   // read/write errors that closed an open socket (down, removed)
  std::uint64_t sent = 0;
  std::uint64_t send_failed = 0;   // writes refused (closed, down, queue full)
};

class CanSocket {
 public:
  // Does not open yet: the first ensure_open / poll / send does.
  explicit CanSocket(std::string ifname, double retry_s = 0.5);
  ~CanSocket();
  CanSocket(const CanSocket&) = delete;
  CanSocket& operator=(const CanSocket&) = delete;

  // Opens when closed and at least retry_s has passed since the last failed
  // attempt (the first attempt is immediate). Returns is_open().
  bool ensure_open(double now_s);
  bool is_open() const { return fd_ >= 0; }

  // Reads every pending frame without blocking (opening first if needed).
  // Data frames go to sink(frame, receive_time_s on the steady clock); error
  // frames are only counted. Returns the number of data frames delivered.
  int poll(const std::function<void(const wire::CanFrame&, double)>& sink);

  // Writes one frame (opening first if needed). False when refused.
  bool send(const wire::CanFrame& frame);

  const std::string& ifname() const { return ifname_; }
  const CanSocketStats& stats() const { return stats_; }
  // The current problem ("" while healthy), e.g. "vcan0: no such interface".
  const std::string& last_error() const { return last_error_; }
  // Bumped whenever last_error changes (to a problem or back to healthy), so
  // a caller can print each change of state once.
  std::uint64_t state_changes() const { return state_changes_; }

 private:
  void fail(const std::string& why);
  void close_socket(const std::string& why);
  void set_healthy();

  std::string ifname_;
  double retry_s_;
  int fd_ = -1;
  double next_try_s_ = -1e300;
  std::uint64_t drops_before_open_ = 0;  // kernel_drops of earlier sockets
  CanSocketStats stats_;
  std::string last_error_;
  std::uint64_t state_changes_ = 0;
};

}  // namespace ig::io::can
