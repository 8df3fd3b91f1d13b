// Receive times are taken per datagram when it arrives (kernel timestamps),
// not when the frame loop reads it: two datagrams sent 50 ms apart and read
// in one poll keep their 50 ms (real UDP sockets on loopback).
#include "io/net/udp_socket.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <thread>
#include <vector>

using namespace ig::io::net;

TEST(UdpReceiveTime, DatagramsReadInOnePollKeepTheirArrivalTimes) {
  UdpReceiver rx("127.0.0.1:0");
  UdpSender tx("127.0.0.1:" + std::to_string(rx.port()));
  // Linux turns receive timestamps on for the whole stack asynchronously
  // after the first socket asks (net_enable_timestamp defers it to a work
  // queue); until then a datagram is stamped when it is read. Warm up until
  // a datagram's stamp predates its read, as a long-running IG's would.
  bool stamps_live = false;
  for (int attempt = 0; attempt < 200 && !stamps_live; ++attempt) {
    ASSERT_TRUE(tx.send(std::vector<std::uint8_t>{0}));
    ASSERT_TRUE(rx.wait_readable(5.0));
    std::this_thread::sleep_for(std::chrono::milliseconds(5));  // read it late
    const double read_at = steady_now_s();
    rx.poll([&](std::span<const std::uint8_t>, double when, const sockaddr_in&) {
      stamps_live = read_at - when >= 0.004;
    });
  }
  ASSERT_TRUE(stamps_live) << "receive timestamps never predated the read";
  const std::uint64_t warm_stamps = rx.stats().kernel_timestamps;
  const std::vector<std::uint8_t> a{1}, b{2};
  const double sent_a = steady_now_s();
  ASSERT_TRUE(tx.send(a));
  // Shapes the stream (the host's send interval); nothing waits on the IG.
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_TRUE(tx.send(b));
  const double sent_b = steady_now_s();
  ASSERT_TRUE(rx.wait_readable(5.0));
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // the frame loop reads late
  std::vector<double> t;
  const double read_at = steady_now_s();
  rx.poll([&](std::span<const std::uint8_t>, double when, const sockaddr_in&) { t.push_back(when); });
  ASSERT_EQ(t.size(), 2u);
  std::printf("[udp] sends spanned %.3f ms, stamped %.3f ms apart; read %.1f ms after the second arrived\n",
              (sent_b - sent_a) * 1e3, (t[1] - t[0]) * 1e3, (read_at - t[1]) * 1e3);
  EXPECT_EQ(rx.stats().kernel_timestamps - warm_stamps, 2u);
  // Loopback stamps a datagram inside send(): the second came at least the
  // 50 ms the sender waited after the first, and no more than the sends span.
  EXPECT_GE(t[1] - t[0], 0.050);
  EXPECT_LE(t[1] - t[0], sent_b - sent_a);
  EXPECT_LE(t[1], read_at);                    // stamped before it was read
  EXPECT_GE(t[0], sent_a - 1e-3);
}

TEST(UdpReceiveTime, WaitReadableTimesOutWithoutData) {
  UdpReceiver rx("127.0.0.1:0");
  EXPECT_FALSE(rx.wait_readable(0.0));
  std::size_t n = rx.poll([](std::span<const std::uint8_t>, double, const sockaddr_in&) {});
  EXPECT_EQ(n, 0u);
}
