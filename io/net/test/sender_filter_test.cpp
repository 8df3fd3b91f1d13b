// Which host a pose source takes datagrams from, on real loopback sockets:
// senders bound to their own ports, the receiver's reported sender address.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "io/net/sender_filter.h"
#include "io/net/udp_socket.h"

namespace ig::io::net {
namespace {

// The senders' addresses as the receiver saw them, in arrival order.
std::vector<sockaddr_in> receive_all(UdpReceiver& rx, std::size_t expected) {
  std::vector<sockaddr_in> from;
  while (from.size() < expected) {
    if (!rx.wait_readable(5.0)) break;
    rx.poll([&](std::span<const std::uint8_t>, double, const sockaddr_in& f) { from.push_back(f); });
  }
  return from;
}

struct TwoHosts {
  UdpReceiver rx{"127.0.0.1:0"};
  std::string to = "127.0.0.1:" + std::to_string(rx.port());
  UdpSender first{to, "127.0.0.1", "127.0.0.1:0"};
  UdpSender second{to, "127.0.0.1", "127.0.0.1:0"};
  std::array<std::uint8_t, 4> bytes{1, 2, 3, 4};
  // first, second, second, first: the addresses as received.
  std::vector<sockaddr_in> interleaved() {
    first.send(bytes);
    auto a = receive_all(rx, 1);
    second.send(bytes);
    second.send(bytes);
    first.send(bytes);
    auto b = receive_all(rx, 3);
    a.insert(a.end(), b.begin(), b.end());
    return a;
  }
};

TEST(SenderFilter, LocksOntoTheFirstSenderAndCountsTheOthers) {
  TwoHosts h;
  const auto from = h.interleaved();
  ASSERT_EQ(from.size(), 4u);
  ASSERT_NE(from[0].sin_port, from[1].sin_port);  // two sockets, one address
  SenderFilter f;
  using V = SenderFilter::Verdict;
  EXPECT_EQ(f.check(from[0]), V::LockedOn);
  EXPECT_EQ(f.check(from[1]), V::FirstForeign);
  EXPECT_EQ(f.check(from[2]), V::Foreign);
  EXPECT_EQ(f.check(from[3]), V::Accept);
  EXPECT_EQ(f.foreign(), 2u);
  EXPECT_EQ(f.locked(), to_string(from[0]));
}

TEST(SenderFilter, TakesOnlyTheHostsItIsTold) {
  TwoHosts h;
  const auto from = h.interleaved();
  ASSERT_EQ(from.size(), 4u);
  // The second sender by its socket: the first is foreign from the start.
  SenderFilter by_socket({parse_host_pattern(to_string(from[1]))});
  EXPECT_EQ(by_socket.check(from[0]), SenderFilter::Verdict::FirstForeign);
  EXPECT_TRUE(SenderFilter::accepted(by_socket.check(from[1])));
  EXPECT_TRUE(SenderFilter::accepted(by_socket.check(from[2])));
  EXPECT_FALSE(SenderFilter::accepted(by_socket.check(from[3])));
  EXPECT_EQ(by_socket.foreign(), 2u);
  EXPECT_FALSE(by_socket.locked());
  // An address without a port: every socket on it.
  SenderFilter by_address({parse_host_pattern("127.0.0.1")});
  for (const auto& f : from) EXPECT_EQ(by_address.check(f), SenderFilter::Verdict::Accept);
  // Another address: nothing from loopback.
  SenderFilter elsewhere({parse_host_pattern("192.0.2.1"), parse_host_pattern("192.0.2.2:5000")});
  for (const auto& f : from) EXPECT_FALSE(SenderFilter::accepted(elsewhere.check(f)));
  EXPECT_EQ(elsewhere.foreign(), 4u);
}

TEST(SenderFilter, HostPatternsParseOrNameTheProblem) {
  EXPECT_EQ(to_string(parse_host_pattern("10.1.2.3")), "10.1.2.3");
  EXPECT_EQ(to_string(parse_host_pattern("10.1.2.3:47000")), "10.1.2.3:47000");
  EXPECT_EQ(to_string(parse_host_pattern("localhost")), "127.0.0.1");
  try {
    parse_host_pattern("10.1.2");
    FAIL() << "a three-part address was taken";
  } catch (const NetError& e) {
    EXPECT_NE(std::string(e.what()).find("\"10.1.2\""), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_host_pattern("10.1.2.3:99999"), NetError);
}

}  // namespace
}  // namespace ig::io::net
