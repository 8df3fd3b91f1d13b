#include "io/net/sender_filter.h"

#include <arpa/inet.h>

#include <algorithm>

#include "io/net/udp_socket.h"

namespace ig::io::net {

bool HostPattern::matches(const sockaddr_in& from) const {
  return from.sin_addr.s_addr == address && (!port || from.sin_port == *port);
}

HostPattern parse_host_pattern(const std::string& text) {
  HostPattern h;
  if (text.find(':') != std::string::npos) {
    const sockaddr_in a = parse_endpoint(text);
    h.address = a.sin_addr.s_addr;
    h.port = a.sin_port;
    return h;
  }
  in_addr a{};
  if (text == "localhost") a.s_addr = htonl(INADDR_LOOPBACK);
  else if (inet_pton(AF_INET, text.c_str(), &a) != 1)
    throw NetError("host \"" + text + "\": not an IPv4 address (ADDR or ADDR:PORT)");
  h.address = a.s_addr;
  return h;
}

std::string to_string(const HostPattern& host) {
  char buf[INET_ADDRSTRLEN] = {};
  in_addr a{};
  a.s_addr = host.address;
  inet_ntop(AF_INET, &a, buf, sizeof buf);
  return host.port ? std::string(buf) + ":" + std::to_string(ntohs(*host.port)) : std::string(buf);
}

SenderFilter::Verdict SenderFilter::check(const sockaddr_in& from) {
  bool ok = false;
  if (!allowed_.empty()) {
    ok = std::any_of(allowed_.begin(), allowed_.end(), [&](const HostPattern& h) { return h.matches(from); });
  } else if (!locked_) {
    locked_ = from;
    return Verdict::LockedOn;
  } else {
    ok = locked_->sin_addr.s_addr == from.sin_addr.s_addr && locked_->sin_port == from.sin_port;
  }
  if (ok) return Verdict::Accept;
  return ++foreign_ == 1 ? Verdict::FirstForeign : Verdict::Foreign;
}

std::optional<std::string> SenderFilter::locked() const {
  if (!locked_) return std::nullopt;
  return to_string(*locked_);
}

}  // namespace ig::io::net
