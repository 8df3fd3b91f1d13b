#include "io/control/modbus_server.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <modbus/modbus.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/select.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <vector>

namespace ig::io::control {
namespace {
using Clock = std::chrono::steady_clock;
constexpr int kMbapLength = 7;  // transaction id, protocol id, length, unit id
constexpr std::size_t kMaxAdu = MODBUS_TCP_MAX_ADU_LENGTH;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
int be16(const std::uint8_t* p) { return (int(p[0]) << 8) | p[1]; }

struct Client {
  int fd = -1;
  bool may_write = true;  // its address is one writes are taken from
  std::vector<std::uint8_t> buf;
  Clock::time_point last_activity = Clock::now();
  std::optional<Clock::time_point> partial_since;  // a request has started but is not complete
};
}  // namespace

ModbusServerOptions parse_modbus_endpoint(const std::string& endpoint) {
  const auto colon = endpoint.rfind(':');
  if (colon == std::string::npos) throw std::invalid_argument("'" + endpoint + "': expected ADDR:PORT");
  ModbusServerOptions o;
  o.address = endpoint.substr(0, colon);
  const std::string port = endpoint.substr(colon + 1);
  char* end = nullptr;
  const long p = port.empty() ? -1 : std::strtol(port.c_str(), &end, 10);
  if (port.empty() || *end != '\0' || p < 0 || p > 65535)
    throw std::invalid_argument("'" + endpoint + "': port must be 0..65535");
  o.port = int(p);
  if (!o.address.empty() && o.address != "0.0.0.0") {
    in_addr a{};
    if (inet_pton(AF_INET, o.address.c_str(), &a) != 1)
      throw std::invalid_argument("'" + endpoint + "': address must be an IPv4 address");
  }
  return o;
}

struct ModbusServer::Impl {
  ModbusServerOptions options;
  modbus_t* ctx = nullptr;
  modbus_mapping_t* mapping = nullptr;
  int listen_fd = -1;
  int wake[2] = {-1, -1};
  std::atomic<bool> stopping{false};
  Clock::time_point started = Clock::now();

  mutable std::mutex mutex;  // guards everything below
  IgStatus status;
  std::array<std::uint16_t, hold::kCount> holding{};
  ControlUpdate pending;  // flags accumulated since the last take_controls
  ModbusServerCounters counters;

  ~Impl() {
    if (listen_fd >= 0) close(listen_fd);
    for (int fd : wake)
      if (fd >= 0) close(fd);
    if (mapping) modbus_mapping_free(mapping);
    if (ctx) modbus_free(ctx);
  }
};

ModbusServer::ModbusServer(const ModbusServerOptions& options, const IgControls& initial)
    : impl_(std::make_unique<Impl>()) {
  auto& m = *impl_;
  m.options = options;
  encode_controls(initial, m.holding);
  if (auto why = validate_controls(m.holding)) throw std::runtime_error("modbus: initial controls invalid: " + *why);
  const bool any = options.address.empty() || options.address == "0.0.0.0";
  m.ctx = modbus_new_tcp(any ? nullptr : options.address.c_str(), options.port);
  if (!m.ctx) throw std::runtime_error(std::string("modbus: ") + modbus_strerror(errno));
  m.mapping = modbus_mapping_new_start_address(0, 0, 0, 0, 0, hold::kCount, 0, in::kCount);
  if (!m.mapping) throw std::runtime_error(std::string("modbus: ") + modbus_strerror(errno));
  m.listen_fd = modbus_tcp_listen(m.ctx, 16);
  if (m.listen_fd < 0)
    throw std::runtime_error("modbus: cannot listen on " + (any ? std::string("*") : options.address) + ":" +
                             std::to_string(options.port) + ": " + modbus_strerror(errno));
  fcntl(m.listen_fd, F_SETFL, fcntl(m.listen_fd, F_GETFL) | O_NONBLOCK);
  sockaddr_in sa{};
  socklen_t len = sizeof sa;
  getsockname(m.listen_fd, reinterpret_cast<sockaddr*>(&sa), &len);
  port_ = ntohs(sa.sin_port);
  if (pipe2(m.wake, O_CLOEXEC | O_NONBLOCK) != 0) throw std::runtime_error("modbus: pipe failed");
  thread_ = std::thread([this] { run(); });
}

ModbusServer::~ModbusServer() { stop(); }

void ModbusServer::stop() {
  if (!impl_ || impl_->stopping.exchange(true)) return;
  const char c = 1;
  [[maybe_unused]] auto n = write(impl_->wake[1], &c, 1);
  if (thread_.joinable()) thread_.join();
}

void ModbusServer::publish(const IgStatus& status) {
  std::lock_guard lock(impl_->mutex);
  impl_->status = status;
}

ControlUpdate ModbusServer::take_controls() {
  std::lock_guard lock(impl_->mutex);
  ControlUpdate u = impl_->pending;
  u.controls = decode_controls(impl_->holding);
  if (u.capture) impl_->holding[hold::kCapture] = 0;
  u.controls.capture = u.capture;
  impl_->pending = ControlUpdate{};
  return u;
}

IgControls ModbusServer::controls() const {
  std::lock_guard lock(impl_->mutex);
  return decode_controls(impl_->holding);
}

ModbusServerCounters ModbusServer::counters() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->counters;
}

void ModbusServer::run() {
  auto& m = *impl_;
  std::vector<Client> clients;
  const int header = modbus_get_header_length(m.ctx);  // 7 for TCP

  auto drop = [&](std::size_t i) {
    close(clients[i].fd);
    clients.erase(clients.begin() + std::ptrdiff_t(i));
    clients_ = int(clients.size());
  };
  auto count_drop = [&] {
    std::lock_guard lock(m.mutex);
    ++m.counters.clients_dropped;
  };

  // Answers one complete request. false: the client must be closed (send failed).
  auto handle = [&](int fd, bool may_write, const std::uint8_t* req, int len) -> bool {
    modbus_set_socket(m.ctx, fd);
    const int fc = req[header];
    int rc = 0;
    bool exception = false;
    auto fail = [&](unsigned code) {
      exception = true;
      rc = modbus_reply_exception(m.ctx, req, code);
    };
    const bool is_read = fc == MODBUS_FC_READ_HOLDING_REGISTERS || fc == MODBUS_FC_READ_INPUT_REGISTERS;
    if (!is_read && fc != MODBUS_FC_WRITE_SINGLE_REGISTER && fc != MODBUS_FC_WRITE_MULTIPLE_REGISTERS) {
      fail(MODBUS_EXCEPTION_ILLEGAL_FUNCTION);
    } else if (!is_read && !may_write) {
      fail(MODBUS_EXCEPTION_ILLEGAL_FUNCTION);  // writes only from the allowed addresses
      std::lock_guard lock(m.mutex);
      ++m.counters.writes_refused;
    } else if (len < header + 5) {
      fail(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE);
    } else {
      const int addr = be16(req + header + 1);
      const int nb = be16(req + header + 3);
      if (is_read) {
        const int size = fc == MODBUS_FC_READ_INPUT_REGISTERS ? in::kCount : hold::kCount;
        if (nb < 1 || nb > MODBUS_MAX_READ_REGISTERS) fail(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE);
        else if (addr + nb > size) fail(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS);
        else {
          {
            std::lock_guard lock(m.mutex);
            IgStatus s = m.status;
            s.uptime_s = std::uint32_t(seconds_since(m.started));
            s.modbus_clients = std::uint16_t(clients.size());
            encode_status(s, std::span<std::uint16_t, in::kCount>(m.mapping->tab_input_registers, in::kCount));
            std::copy(m.holding.begin(), m.holding.end(), m.mapping->tab_registers);
          }
          rc = modbus_reply(m.ctx, req, len, m.mapping);
        }
      } else {
        // The write as (first register, values), checked as a whole.
        std::vector<std::uint16_t> values;
        bool malformed = false;
        if (fc == MODBUS_FC_WRITE_SINGLE_REGISTER) {
          values.push_back(std::uint16_t(nb));
        } else {
          const int bytes = len > header + 5 ? req[header + 5] : -1;
          if (nb < 1 || nb > MODBUS_MAX_WRITE_REGISTERS || bytes != nb * 2 || len < header + 6 + bytes)
            malformed = true;
          else
            for (int k = 0; k < nb; ++k) values.push_back(std::uint16_t(be16(req + header + 6 + 2 * k)));
        }
        if (malformed) fail(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE);
        else if (addr + int(values.size()) > hold::kCount) fail(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS);
        else {
          bool ok = false;
          {
            std::lock_guard lock(m.mutex);
            auto candidate = m.holding;
            std::copy(values.begin(), values.end(), candidate.begin() + addr);
            if (!validate_controls(candidate)) {
              ok = true;
              const IgControls before = decode_controls(m.holding), after = decode_controls(candidate);
              m.pending.thresholds |= before.a1 != after.a1 || before.a2 != after.a2;
              m.pending.rebuild |= before.alpha != after.alpha || before.level0_budget != after.level0_budget;
              m.pending.fog |= before.fog_visibility_m != after.fog_visibility_m;
              m.pending.latency |= before.latency_mode != after.latency_mode;
              if (addr <= hold::kCapture && addr + int(values.size()) > hold::kCapture)
                m.pending.capture = after.capture;
              m.holding = candidate;
              ++m.counters.writes_applied;
              std::copy(m.holding.begin(), m.holding.end(), m.mapping->tab_registers);
            }
          }
          if (ok) rc = modbus_reply(m.ctx, req, len, m.mapping);
          else fail(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE);
        }
      }
    }
    {
      std::lock_guard lock(m.mutex);
      ++m.counters.requests;
      if (exception) ++m.counters.exceptions;
    }
    return rc >= 0;
  };

  std::uint8_t chunk[1024];
  while (!m.stopping) {
    fd_set rd;
    FD_ZERO(&rd);
    FD_SET(m.wake[0], &rd);
    FD_SET(m.listen_fd, &rd);
    int max_fd = std::max(m.wake[0], m.listen_fd);
    for (const auto& c : clients) {
      FD_SET(c.fd, &rd);
      max_fd = std::max(max_fd, c.fd);
    }
    timeval tv{0, 100000};  // wake up for the timeouts
    const int n = select(max_fd + 1, &rd, nullptr, nullptr, &tv);
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    if (FD_ISSET(m.wake[0], &rd)) break;
    if (n > 0 && FD_ISSET(m.listen_fd, &rd)) {
      for (;;) {
        sockaddr_in peer{};
        socklen_t peer_size = sizeof peer;
        const int fd =
            accept4(m.listen_fd, reinterpret_cast<sockaddr*>(&peer), &peer_size, SOCK_NONBLOCK | SOCK_CLOEXEC);
        if (fd < 0) break;
        const auto& writers = m.options.writers;
        const bool may_write =
            writers.empty() || std::find(writers.begin(), writers.end(), peer.sin_addr.s_addr) != writers.end();
        const int one = 1;
        setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
        std::lock_guard lock(m.mutex);
        ++m.counters.clients_accepted;
        if (int(clients.size()) >= m.options.max_clients || fd >= FD_SETSIZE) {
          close(fd);
          ++m.counters.clients_dropped;
          continue;
        }
        clients.push_back(Client{fd, may_write, {}, Clock::now(), std::nullopt});
        clients_ = int(clients.size());
      }
    }
    for (std::size_t i = clients.size(); i-- > 0;) {
      Client& c = clients[i];
      bool close_it = false, dropped = false;
      if (n > 0 && FD_ISSET(c.fd, &rd)) {
        const ssize_t got = recv(c.fd, chunk, sizeof chunk, 0);
        if (got == 0 || (got < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
          close_it = true;  // the client went away
        } else if (got > 0) {
          c.last_activity = Clock::now();
          c.buf.insert(c.buf.end(), chunk, chunk + got);
          // Every complete request in the buffer, in order.
          std::size_t off = 0;
          while (!close_it && c.buf.size() - off >= std::size_t(kMbapLength)) {
            const std::uint8_t* p = c.buf.data() + off;
            const int protocol = be16(p + 2), length = be16(p + 4);
            // MBAP length counts unit id + PDU: at least unit + function code.
            if (protocol != 0 || length < 2 || std::size_t(6 + length) > kMaxAdu) {
              close_it = dropped = true;  // garbage: not Modbus TCP
              break;
            }
            const std::size_t total = 6 + std::size_t(length);
            if (c.buf.size() - off < total) break;
            if (!handle(c.fd, c.may_write, p, int(total))) close_it = dropped = true;
            off += total;
          }
          c.buf.erase(c.buf.begin(), c.buf.begin() + std::ptrdiff_t(std::min(off, c.buf.size())));
          if (c.buf.empty()) c.partial_since.reset();
          else if (!c.partial_since) c.partial_since = Clock::now();
        }
      }
      if (!close_it && c.partial_since && seconds_since(*c.partial_since) > m.options.request_timeout_s)
        close_it = dropped = true;  // half a request and nothing more
      if (!close_it && seconds_since(c.last_activity) > m.options.idle_timeout_s) close_it = dropped = true;
      if (close_it) {
        if (dropped) count_drop();
        drop(i);
      }
    }
  }
  for (auto& c : clients) close(c.fd);
  clients.clear();
  clients_ = 0;
}

}  // namespace ig::io::control
