#pragma once
// UDP transport for pose intake and replies: non-blocking receive (the frame
// loop polls; it never waits on the network), optional multicast group
// membership, unicast or multicast send. Bytes only: decoding lives in
// io/wire, so a transport never knows a protocol and never touches GL.

#include <netinet/in.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

namespace ig::io::net {

struct NetError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "ADDR:PORT" (IPv4 dotted quad or a name resolvable without a network, e.g.
// localhost). Throws NetError naming the text and the problem.
sockaddr_in parse_endpoint(const std::string& text);
std::string to_string(const sockaddr_in& address);
bool is_multicast(const sockaddr_in& address);

struct ReceiveStats {
  std::uint64_t datagrams = 0;
  std::uint64_t bytes = 0;
  std::uint64_t truncated = 0;  // larger than the receive buffer (dropped)
  std::uint64_t errors = 0;
  std::uint64_t kernel_timestamps = 0;  // datagrams with a kernel receive time (SO_TIMESTAMPNS)
};

// A UDP socket's descriptor (SOCK_CLOEXEC plus `flags`), closed when
// destroyed, so neither the sockets below nor a constructor that throws
// half way leaves it open; not copyable. Throws NetError "udp WHAT: socket:
// reason" when the kernel gives none.
class UdpDescriptor {
 public:
  UdpDescriptor(int flags, const std::string& what);
  ~UdpDescriptor();
  UdpDescriptor(const UdpDescriptor&) = delete;
  UdpDescriptor& operator=(const UdpDescriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

class UdpReceiver {
 public:
  // Binds ADDR:PORT (SO_REUSEADDR + SO_REUSEPORT so several IG channel
  // processes can share a multicast port). A multicast bind address joins the
  // group on `interface_address` (default loopback). Throws NetError.
  explicit UdpReceiver(const std::string& bind_endpoint, const std::string& interface_address = "127.0.0.1");

  using Handler = std::function<void(std::span<const std::uint8_t> datagram, double receive_time_s,
                                     const sockaddr_in& from)>;
  // Hands every datagram that has already arrived to `handler` (at most
  // max_datagrams), with its receive time on the steady clock in seconds:
  // the kernel's arrival stamp (SO_TIMESTAMPNS), or the clock read for that
  // datagram when the kernel gave none. Never blocks.
  std::size_t poll(const Handler& handler, std::size_t max_datagrams = 4096);
  // Blocks until a datagram is waiting or timeout_s passes (CIGI synchronous
  // operation waits on the host this way). true: one is waiting.
  bool wait_readable(double timeout_s) const;
  const ReceiveStats& stats() const { return stats_; }
  std::uint16_t port() const;  // the bound port (useful with port 0)
  int fd() const { return fd_.get(); }
  // A reply from the bound port to `to` (a datagram's sender). false when
  // the kernel refused; never blocks for long, never throws.
  bool send_to(std::span<const std::uint8_t> datagram, const sockaddr_in& to);

 private:
  UdpDescriptor fd_;
  ReceiveStats stats_;
};

class UdpSender {
 public:
  // Unicast or multicast destination; multicast goes out on
  // `interface_address` with TTL 1 and loopback enabled.
  // `from`: send from this ADDR:PORT (a host that must be told apart by its
  // socket); default: any port the kernel picks.
  explicit UdpSender(const std::string& destination, const std::string& interface_address = "127.0.0.1",
                     const std::optional<std::string>& from = std::nullopt);
  // false when the kernel refused (counted by the caller); never throws.
  bool send(std::span<const std::uint8_t> datagram);
  bool send_to(std::span<const std::uint8_t> datagram, const sockaddr_in& to);

 private:
  UdpDescriptor fd_;
  sockaddr_in destination_{};
};

// Seconds on the steady clock (the IG's clock for receive times and frames).
double steady_now_s();

}  // namespace ig::io::net
