#include "io/can/can_socket.h"

#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "io/net/udp_socket.h"

namespace ig::io::can {
namespace {

std::string errno_text(int e) { return std::strerror(e); }

wire::CanFrame from_kernel(const canfd_frame& k, bool fd) {
  wire::CanFrame f;
  const bool ext = (k.can_id & CAN_EFF_FLAG) != 0;
  f.id = k.can_id & (ext ? CAN_EFF_MASK : CAN_SFF_MASK);
  if (ext) f.flags |= wire::kCanFlagExtended;
  if (k.can_id & CAN_RTR_FLAG) f.flags |= wire::kCanFlagRtr;
  if (fd) f.flags |= wire::kCanFlagFd;
  if (fd && (k.flags & CANFD_BRS)) f.flags |= wire::kCanFlagBrs;
  f.len = std::min<std::uint8_t>(k.len, fd ? CANFD_MAX_DLEN : CAN_MAX_DLEN);
  std::memcpy(f.data.data(), k.data, f.len);
  return f;
}

}  // namespace

CanSocket::CanSocket(std::string ifname, double retry_s) : ifname_(std::move(ifname)), retry_s_(retry_s) {}

CanSocket::~CanSocket() {
  if (fd_ >= 0) ::close(fd_);
}

void CanSocket::fail(const std::string& why) {
  ++stats_.open_failures;
  if (why != last_error_) {
    last_error_ = why;
    ++state_changes_;
  }
}

void CanSocket::close_socket(const std::string& why) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ++stats_.link_errors;
  next_try_s_ = net::steady_now_s() + retry_s_;
  if (why != last_error_) {
    last_error_ = why;
    ++state_changes_;
  }
}

void CanSocket::set_healthy() {
  if (!last_error_.empty()) {
    last_error_.clear();
    ++state_changes_;
  }
}

bool CanSocket::ensure_open(double now_s) {
  if (fd_ >= 0) return true;
  if (now_s < next_try_s_) return false;
  next_try_s_ = now_s + retry_s_;
  if (ifname_.empty() || ifname_.size() >= IFNAMSIZ) {
    fail("'" + ifname_ + "': not a valid interface name");
    return false;
  }
  const int s = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
  if (s < 0) {
    const int e = errno;
    fail(ifname_ + ": socket(AF_CAN): " + errno_text(e) +
         (e == EAFNOSUPPORT ? " (this kernel has no SocketCAN; see docs/can.md)" : ""));
    return false;
  }
  ifreq ifr{};
  std::strncpy(ifr.ifr_name, ifname_.c_str(), IFNAMSIZ - 1);
  if (::ioctl(s, SIOCGIFINDEX, &ifr) < 0) {
    const int e = errno;
    ::close(s);
    fail(ifname_ + ": " + (e == ENODEV ? std::string("no such interface") : errno_text(e)));
    return false;
  }
  const int index = ifr.ifr_ifindex;
  if (::ioctl(s, SIOCGIFFLAGS, &ifr) == 0 && !(ifr.ifr_flags & IFF_UP)) {
    ::close(s);
    fail(ifname_ + ": interface is down");
    return false;
  }
  // FD frames when the interface has the FD MTU; a classic interface just
  // never delivers any. Every error class is reported as an error frame.
  const int on = 1;
  ::setsockopt(s, SOL_CAN_RAW, CAN_RAW_FD_FRAMES, &on, sizeof(on));
  const can_err_mask_t err_mask = CAN_ERR_MASK;
  ::setsockopt(s, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &err_mask, sizeof(err_mask));
  ::setsockopt(s, SOL_SOCKET, SO_RXQ_OVFL, &on, sizeof(on));
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = index;
  if (::bind(s, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) < 0) {
    const int e = errno;
    ::close(s);
    fail(ifname_ + ": bind: " + errno_text(e));
    return false;
  }
  fd_ = s;
  drops_before_open_ = stats_.kernel_drops;
  ++stats_.opens;
  set_healthy();
  return true;
}

int CanSocket::poll(const std::function<void(const wire::CanFrame&, double)>& sink) {
  if (!ensure_open(net::steady_now_s())) return 0;
  int delivered = 0;
  for (;;) {
    canfd_frame k{};
    iovec iov{&k, sizeof(k)};
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(std::uint32_t))];
    msghdr msg{};
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control;
    msg.msg_controllen = sizeof(control);
    const ssize_t n = ::recvmsg(fd_, &msg, 0);
    if (n < 0) {
      const int e = errno;
      if (e == EAGAIN || e == EWOULDBLOCK) break;
      if (e == EINTR) continue;
      // ENETDOWN (link down) and ENODEV (interface removed) land here: close
      // and reopen by name, which also rebinds to a re-created interface.
      close_socket(ifname_ + ": " + (e == ENETDOWN ? std::string("interface went down") :
                                     e == ENODEV   ? std::string("interface was removed") : errno_text(e)));
      break;
    }
    for (cmsghdr* c = CMSG_FIRSTHDR(&msg); c; c = CMSG_NXTHDR(&msg, c)) {
      if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SO_RXQ_OVFL) {
        std::uint32_t dropped = 0;
        std::memcpy(&dropped, CMSG_DATA(c), sizeof(dropped));
        stats_.kernel_drops = drops_before_open_ + dropped;  // the kernel counts per socket
      }
    }
    if (n != CAN_MTU && n != CANFD_MTU) continue;  // not a frame the kernel defines
    if (k.can_id & CAN_ERR_FLAG) {
      ++stats_.error_frames;
      if (k.can_id & CAN_ERR_BUSOFF) ++stats_.bus_off;
      continue;
    }
    const bool fd = n == CANFD_MTU;
    ++stats_.frames;
    if (fd) ++stats_.fd_frames;
    sink(from_kernel(k, fd), net::steady_now_s());
    ++delivered;
  }
  return delivered;
}

bool CanSocket::send(const wire::CanFrame& f) {
  if (!ensure_open(net::steady_now_s())) {
    ++stats_.send_failed;
    return false;
  }
  canfd_frame k{};
  k.can_id = f.id & (f.is_extended() ? CAN_EFF_MASK : CAN_SFF_MASK);
  if (f.is_extended()) k.can_id |= CAN_EFF_FLAG;
  if (f.flags & wire::kCanFlagRtr) k.can_id |= CAN_RTR_FLAG;
  if (f.flags & wire::kCanFlagError) k.can_id |= CAN_ERR_FLAG;
  const bool fd = f.is_fd();
  k.len = std::min<std::uint8_t>(f.len, fd ? CANFD_MAX_DLEN : CAN_MAX_DLEN);
  if (fd && (f.flags & wire::kCanFlagBrs)) k.flags |= CANFD_BRS;
  std::memcpy(k.data, f.data.data(), k.len);
  const ssize_t want = fd ? CANFD_MTU : CAN_MTU;
  const ssize_t n = ::write(fd_, &k, size_t(want));
  if (n == want) {
    ++stats_.sent;
    return true;
  }
  const int e = n < 0 ? errno : EIO;
  ++stats_.send_failed;
  // A full queue (ENOBUFS) is transient; down / removed closes and retries.
  if (e == ENETDOWN || e == ENODEV || e == ENXIO)
    close_socket(ifname_ + ": " + (e == ENETDOWN ? std::string("interface went down") :
                                   std::string("interface was removed")));
  return false;
}

}  // namespace ig::io::can
