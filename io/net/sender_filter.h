#pragma once
// Which hosts a UDP pose source takes datagrams from. Two hosts pointed at
// one IG by mistake must not blend their poses, and a stray process on the
// network must not move the ownship: a source takes datagrams only from the
// hosts it was told (ADDR, any port, or ADDR:PORT), or, told none, from the
// first sender it hears (its address and port), and drops everyone else's.

#include <netinet/in.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ig::io::net {

// "ADDR" (any port) or "ADDR:PORT". Throws NetError naming the text.
struct HostPattern {
  in_addr_t address = 0;        // network byte order
  std::optional<in_port_t> port;  // network byte order; nullopt: any port
  bool matches(const sockaddr_in& from) const;
};
HostPattern parse_host_pattern(const std::string& text);
std::string to_string(const HostPattern& host);

class SenderFilter {
 public:
  // Empty `allowed`: lock onto the first sender.
  explicit SenderFilter(std::vector<HostPattern> allowed = {}) : allowed_(std::move(allowed)) {}

  enum class Verdict : std::uint8_t {
    Accept,       // from an allowed host
    LockedOn,     // the first sender: accepted, and from now the only one
    Foreign,      // dropped; counted
    FirstForeign  // dropped; the first from anyone else (warn once)
  };
  Verdict check(const sockaddr_in& from);
  static bool accepted(Verdict v) { return v == Verdict::Accept || v == Verdict::LockedOn; }

  std::uint64_t foreign() const { return foreign_; }
  // "ADDR:PORT" this source locked onto, when it locked onto one.
  std::optional<std::string> locked() const;

 private:
  std::vector<HostPattern> allowed_;
  std::optional<sockaddr_in> locked_;
  std::uint64_t foreign_ = 0;
};

}  // namespace ig::io::net
