#include "io/net/udp_socket.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
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

UdpReceiver::UdpReceiver(const std::string& bind_endpoint, const std::string& interface_address) {
  const sockaddr_in addr = parse_endpoint(bind_endpoint);
  fd_ = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw NetError("udp " + bind_endpoint + ": socket: " + errno_text());
  const int one = 1;
  setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  setsockopt(fd_, SOL_SOCKET, SO_REUSEPORT, &one, sizeof one);
  const int rcvbuf = 4 << 20;  // absorb bursts between frames
  setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &rcvbuf, sizeof rcvbuf);
  if (bind(fd_, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0) {
    const std::string e = errno_text();
    close(fd_);
    throw NetError("udp " + bind_endpoint + ": bind: " + e);
  }
  if (is_multicast(addr)) {
    ip_mreq m{};
    m.imr_multiaddr = addr.sin_addr;
    m.imr_interface = parse_address(interface_address, "multicast interface");
    if (setsockopt(fd_, IPPROTO_IP, IP_ADD_MEMBERSHIP, &m, sizeof m) != 0) {
      const std::string e = errno_text();
      close(fd_);
      throw NetError("udp " + bind_endpoint + ": join multicast group on " + interface_address + ": " + e);
    }
  }
}

UdpReceiver::~UdpReceiver() {
  if (fd_ >= 0) close(fd_);
}

std::uint16_t UdpReceiver::port() const {
  sockaddr_in a{};
  socklen_t len = sizeof a;
  getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &len);
  return ntohs(a.sin_port);
}

std::size_t UdpReceiver::poll(const Handler& handler, std::size_t max_datagrams) {
  // One byte more than the largest datagram we accept, so oversize ones are seen (MSG_TRUNC).
  static thread_local std::vector<std::uint8_t> buf(65536);
  std::size_t n = 0;
  while (n < max_datagrams) {
    sockaddr_in from{};
    socklen_t len = sizeof from;
    const ssize_t got = recvfrom(fd_, buf.data(), buf.size(), MSG_TRUNC, reinterpret_cast<sockaddr*>(&from), &len);
    if (got < 0) {
      if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) ++stats_.errors;
      break;
    }
    ++n;
    ++stats_.datagrams;
    stats_.bytes += std::uint64_t(got);
    if (std::size_t(got) > buf.size()) {
      ++stats_.truncated;
      continue;
    }
    handler(std::span<const std::uint8_t>(buf.data(), std::size_t(got)), steady_now_s(), from);
  }
  return n;
}

UdpSender::UdpSender(const std::string& destination, const std::string& interface_address)
    : destination_(parse_endpoint(destination)) {
  fd_ = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw NetError("udp " + destination + ": socket: " + errno_text());
  if (is_multicast(destination_)) {
    const in_addr itf = parse_address(interface_address, "multicast interface");
    setsockopt(fd_, IPPROTO_IP, IP_MULTICAST_IF, &itf, sizeof itf);
    const unsigned char ttl = 1, loop = 1;
    setsockopt(fd_, IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof ttl);
    setsockopt(fd_, IPPROTO_IP, IP_MULTICAST_LOOP, &loop, sizeof loop);
  }
}

UdpSender::~UdpSender() {
  if (fd_ >= 0) close(fd_);
}

bool UdpSender::send(std::span<const std::uint8_t> d) { return send_to(d, destination_); }

bool UdpSender::send_to(std::span<const std::uint8_t> d, const sockaddr_in& to) {
  return sendto(fd_, d.data(), d.size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof to) ==
         ssize_t(d.size());
}

}  // namespace ig::io::net
