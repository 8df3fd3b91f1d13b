#pragma once
// Modbus TCP status and control server for ig serve (docs/modbus.md).
//
// Runs in its own thread: select() over the listening socket and every client
// socket, reads requests into a per-client buffer (non-blocking, so a client
// that sends half a request and goes quiet never stalls the others; it is
// dropped after request_timeout_s), and answers whole requests with
// modbus_reply / modbus_reply_exception. Garbage (a bad MBAP header) closes
// that client only.
//
// The frame loop never waits on the server: publish() copies a status
// snapshot in and take_controls() copies the control image out, each under a
// mutex held only for the copy. Writes are validated against the register
// map (register_map.h) as a whole: an out-of-range value (or a1 >= a2) gets
// ILLEGAL_DATA_VALUE and changes nothing, also for multi-register writes.

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "io/control/ig_status.h"
#include "io/control/register_map.h"

namespace ig::io::control {

struct ModbusServerOptions {
  std::string address = "127.0.0.1";  // "" or "0.0.0.0": all interfaces
  int port = 502;                      // 0: any free port (see ModbusServer::port())
  int max_clients = 64;                // more connections are accepted and closed at once
  double request_timeout_s = 1.0;      // a started request must be complete within this
  double idle_timeout_s = 300.0;       // a silent client is closed after this
  // Addresses (IPv4, network byte order) writes are taken from; a write from
  // any other gets ILLEGAL_FUNCTION and changes nothing. Empty: anyone.
  std::vector<std::uint32_t> writers;
};

// "ADDR:PORT" (ADDR may be empty: ":1502" = all interfaces). Throws
// std::invalid_argument with a one-line reason.
ModbusServerOptions parse_modbus_endpoint(const std::string& endpoint);

struct ModbusServerCounters {
  std::uint64_t requests = 0;         // answered requests (replies + exceptions)
  std::uint64_t exceptions = 0;       // answered with an exception
  std::uint64_t writes_applied = 0;   // accepted FC 06 / 16 writes
  std::uint64_t writes_refused = 0;   // FC 06 / 16 from an address not allowed to write
  std::uint64_t clients_accepted = 0;
  std::uint64_t clients_dropped = 0;  // closed by the server: garbage, timeout, full, send failure
};

class ModbusServer {
 public:
  // Binds and listens, then starts the thread. `initial` is the controls'
  // starting image (what the IG runs with). Throws std::runtime_error.
  ModbusServer(const ModbusServerOptions& options, const IgControls& initial);
  ~ModbusServer();
  ModbusServer(const ModbusServer&) = delete;
  ModbusServer& operator=(const ModbusServer&) = delete;

  int port() const { return port_; }
  // Frame loop side: never blocks beyond a short copy.
  void publish(const IgStatus& status);
  // The current control image and what was written since the last call
  // (a pending capture trigger is consumed: its register reads 0 again).
  ControlUpdate take_controls();
  IgControls controls() const;
  ModbusServerCounters counters() const;
  int clients() const { return clients_.load(); }
  void stop();  // idempotent; the destructor calls it

 private:
  struct Impl;
  void run();
  std::unique_ptr<Impl> impl_;
  int port_ = 0;
  std::atomic<int> clients_{0};
  std::thread thread_;
};

}  // namespace ig::io::control
