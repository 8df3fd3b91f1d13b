#include "io/net/udp_socket.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <algorithm>
#include <vector>

namespace ig::io::net {
namespace {

std::string errno_text() { return std::strerror(errno); }

in_addr parse_address(const std::string& host, const std::string& what) {
  in_addr a{};
  if (inet_pton(AF_INET, host.c_str(), &a) == 1) return a;
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_DGRAM;
  addrinfo* res = nullptr;
  if (getaddrinfo(host.c_str(), nullptr, &hints, &res) != 0 || !res)
    throw NetError(what + ": cannot resolve host '" + host + "'");
  a = reinterpret_cast<sockaddr_in*>(res->ai_addr)->sin_addr;
  freeaddrinfo(res);
  return a;
}

double timespec_s(const timespec& t) { return double(t.tv_sec) + double(t.tv_nsec) * 1e-9; }

// The kernel stamps datagrams on CLOCK_REALTIME; the IG runs on the steady
// clock. Map through the two clocks read together: the realtime clock is
// read just before and just after the steady one, and a pair split by a
// preemption (reads more than 20 us apart, seen on a loaded 2-core machine)
// is read again, so a busy machine does not shift the stamps. A stamp that
// is in the future or more than 10 s old (the realtime clock was stepped) is
// not trusted: the read time is used instead.
struct ClockPair {
  double realtime_s = 0.0;
  double steady_s = 0.0;
};

ClockPair read_clock_pair() {
  ClockPair best;
  double best_gap = 1e9;
  for (int attempt = 0; attempt < 4 && best_gap > 20e-6; ++attempt) {
    timespec before{}, after{};
    clock_gettime(CLOCK_REALTIME, &before);
    const double steady = steady_now_s();
    clock_gettime(CLOCK_REALTIME, &after);
    const double gap = timespec_s(after) - timespec_s(before);
    if (gap < best_gap) {
      best_gap = gap;
      best = {0.5 * (timespec_s(before) + timespec_s(after)), steady};
    }
  }
  return best;
}

double kernel_stamp_to_steady(const timespec& kernel, const ClockPair& now, bool& used) {
  const double age = now.realtime_s - timespec_s(kernel);
  used = age >= 0.0 && age < 10.0;
  return used ? now.steady_s - age : now.steady_s;
}

}  // namespace

sockaddr_in parse_endpoint(const std::string& text) {
  const auto colon = text.rfind(':');
  if (colon == std::string::npos || colon + 1 >= text.size())
    throw NetError("'" + text + "': expected ADDR:PORT");
  const std::string host = text.substr(0, colon), port_text = text.substr(colon + 1);
  char* end = nullptr;
  const long port = std::strtol(port_text.c_str(), &end, 10);
  if (*end != '\0' || port < 0 || port > 65535) throw NetError("'" + text + "': port must be 0..65535");
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(std::uint16_t(port));
  a.sin_addr = host.empty() || host == "*" ? in_addr{htonl(INADDR_ANY)} : parse_address(host, "'" + text + "'");
  return a;
}

std::string to_string(const sockaddr_in& a) {
  char buf[INET_ADDRSTRLEN] = {};
  inet_ntop(AF_INET, &a.sin_addr, buf, sizeof buf);
  return std::string(buf) + ":" + std::to_string(ntohs(a.sin_port));
}

bool is_multicast(const sockaddr_in& a) { return IN_MULTICAST(ntohl(a.sin_addr.s_addr)); }

double steady_now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

UdpDescriptor::UdpDescriptor(int flags, const std::string& what)
    : fd_(socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC | flags, 0)) {
  if (fd_ < 0) {
    const std::string e = errno_text();
    throw NetError("udp " + what + ": socket: " + e);
  }
}

UdpDescriptor::~UdpDescriptor() { close(fd_); }

UdpReceiver::UdpReceiver(const std::string& bind_endpoint, const std::string& interface_address)
    : fd_(SOCK_NONBLOCK, bind_endpoint) {
  const sockaddr_in addr = parse_endpoint(bind_endpoint);
  const int fd = fd_.get();
  const int one = 1;
  setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  setsockopt(fd, SOL_SOCKET, SO_REUSEPORT, &one, sizeof one);
  const int rcvbuf = 4 << 20;  // absorb bursts between frames
  setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &rcvbuf, sizeof rcvbuf);
  // Receive time per datagram, taken by the kernel when it arrived (not when
  // the frame loop gets round to reading it).
  setsockopt(fd, SOL_SOCKET, SO_TIMESTAMPNS, &one, sizeof one);
  if (bind(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0) {
    const std::string e = errno_text();
    throw NetError("udp " + bind_endpoint + ": bind: " + e);
  }
  if (is_multicast(addr)) {
    ip_mreq m{};
    m.imr_multiaddr = addr.sin_addr;
    m.imr_interface = parse_address(interface_address, "multicast interface");
    if (setsockopt(fd, IPPROTO_IP, IP_ADD_MEMBERSHIP, &m, sizeof m) != 0) {
      const std::string e = errno_text();
      throw NetError("udp " + bind_endpoint + ": join multicast group on " + interface_address + ": " + e);
    }
  }
}

std::uint16_t UdpReceiver::port() const {
  sockaddr_in a{};
  socklen_t len = sizeof a;
  getsockname(fd_.get(), reinterpret_cast<sockaddr*>(&a), &len);
  return ntohs(a.sin_port);
}

std::size_t UdpReceiver::poll(const Handler& handler, std::size_t max_datagrams) {
  // One byte more than the largest datagram we accept, so oversize ones are seen (MSG_TRUNC).
  static thread_local std::vector<std::uint8_t> buf(65536);
  std::size_t n = 0;
  while (n < max_datagrams) {
    sockaddr_in from{};
    iovec iov{buf.data(), buf.size()};
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(timespec))];
    msghdr msg{};
    msg.msg_name = &from;
    msg.msg_namelen = sizeof from;
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control;
    msg.msg_controllen = sizeof control;
    const ssize_t got = recvmsg(fd_.get(), &msg, MSG_TRUNC);
    if (got < 0) {
      if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) ++stats_.errors;
      break;
    }
    const ClockPair now = read_clock_pair();  // per datagram, never once per poll
    double received = now.steady_s;
    bool kernel = false;
    for (cmsghdr* c = CMSG_FIRSTHDR(&msg); c; c = CMSG_NXTHDR(&msg, c)) {
      if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SCM_TIMESTAMPNS) {
        timespec ts{};
        std::memcpy(&ts, CMSG_DATA(c), sizeof ts);
        received = kernel_stamp_to_steady(ts, now, kernel);
      }
    }
    ++n;
    ++stats_.datagrams;
    stats_.bytes += std::uint64_t(got);
    if (kernel) ++stats_.kernel_timestamps;
    if (std::size_t(got) > buf.size()) {
      ++stats_.truncated;
      continue;
    }
    handler(std::span<const std::uint8_t>(buf.data(), std::size_t(got)), received, from);
  }
  return n;
}

bool UdpReceiver::wait_readable(double timeout_s) const {
  pollfd p{fd_.get(), POLLIN, 0};
  const int ms = timeout_s <= 0.0 ? 0 : int(std::min(timeout_s, 3600.0) * 1000.0 + 0.5);
  return ::poll(&p, 1, ms) > 0 && (p.revents & POLLIN);
}

UdpSender::UdpSender(const std::string& destination, const std::string& interface_address,
                     const std::optional<std::string>& from)
    : fd_(0, destination), destination_(parse_endpoint(destination)) {
  if (from) {
    const sockaddr_in local = parse_endpoint(*from);
    if (bind(fd_.get(), reinterpret_cast<const sockaddr*>(&local), sizeof local) != 0)
      throw NetError("udp send from " + *from + ": bind: " + std::strerror(errno));
  }
  if (is_multicast(destination_)) {
    const in_addr itf = parse_address(interface_address, "multicast interface");
    setsockopt(fd_.get(), IPPROTO_IP, IP_MULTICAST_IF, &itf, sizeof itf);
    const unsigned char ttl = 1, loop = 1;
    setsockopt(fd_.get(), IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof ttl);
    setsockopt(fd_.get(), IPPROTO_IP, IP_MULTICAST_LOOP, &loop, sizeof loop);
  }
}

bool UdpSender::send(std::span<const std::uint8_t> d) { return send_to(d, destination_); }

bool UdpReceiver::send_to(std::span<const std::uint8_t> d, const sockaddr_in& to) {
  return sendto(fd_.get(), d.data(), d.size(), MSG_DONTWAIT, reinterpret_cast<const sockaddr*>(&to), sizeof to) ==
         ssize_t(d.size());
}

bool UdpSender::send_to(std::span<const std::uint8_t> d, const sockaddr_in& to) {
  return sendto(fd_.get(), d.data(), d.size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof to) ==
         ssize_t(d.size());
}

}  // namespace ig::io::net
