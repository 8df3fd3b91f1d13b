#pragma once
// A plain CAN frame (classic CAN 2.0 or CAN FD) for the host-side codecs.
// Independent of <linux/can.h> so the codecs and their tests build anywhere;
// the SocketCAN transport converts to / from struct can_frame / canfd_frame.

#include <array>
#include <cstddef>
#include <cstdint>

namespace ig::io::wire {

inline constexpr std::uint32_t kCanStdIdMask = 0x7FFu;       // 11-bit (CAN 2.0A)
inline constexpr std::uint32_t kCanExtIdMask = 0x1FFFFFFFu;  // 29-bit (CAN 2.0B)
inline constexpr std::size_t kCanMaxLen = 8;                 // classic payload
inline constexpr std::size_t kCanFdMaxLen = 64;              // FD payload

// CanFrame::flags bits.
inline constexpr std::uint8_t kCanFlagFd = 1u << 0;        // CAN FD frame
inline constexpr std::uint8_t kCanFlagBrs = 1u << 1;       // FD bit-rate switch
inline constexpr std::uint8_t kCanFlagExtended = 1u << 2;  // 29-bit identifier
inline constexpr std::uint8_t kCanFlagRtr = 1u << 3;       // remote request
inline constexpr std::uint8_t kCanFlagError = 1u << 4;     // error frame

struct CanFrame {
  std::uint32_t id = 0;    // 11-bit unless kCanFlagExtended
  std::uint8_t flags = 0;  // kCanFlag* bits
  // Payload length in bytes (not the raw DLC code): 0..8 classic; FD only
  // 0..8, 12, 16, 20, 24, 32, 48, 64. Bytes past len are don't-care.
  std::uint8_t len = 0;
  std::array<std::uint8_t, kCanFdMaxLen> data{};

  bool is_fd() const { return (flags & kCanFlagFd) != 0; }
  bool is_extended() const { return (flags & kCanFlagExtended) != 0; }
};

// DLC code (0..15) <-> payload length. Classic CAN: DLC 9..15 mean 8 bytes.
inline std::size_t can_dlc_to_len(std::uint8_t dlc, bool fd) {
  static constexpr std::uint8_t kFd[16] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64};
  dlc &= 0x0Fu;
  if (!fd) return dlc > 8 ? 8 : dlc;
  return kFd[dlc];
}

// Smallest DLC code whose length holds `len` bytes (FD pads up); len > 64
// (or > 8 classic) gives the largest code.
inline std::uint8_t can_len_to_dlc(std::size_t len, bool fd) {
  if (len <= 8) return static_cast<std::uint8_t>(len);
  if (!fd) return 8;
  static constexpr std::uint8_t kFd[7] = {12, 16, 20, 24, 32, 48, 64};
  for (std::uint8_t i = 0; i < 7; ++i) {
    if (len <= kFd[i]) return static_cast<std::uint8_t>(9 + i);
  }
  return 15;
}

// True when `len` is a length a frame of that kind can have on the bus.
inline bool can_len_valid(std::size_t len, bool fd) {
  if (len <= 8) return true;
  return fd && can_dlc_to_len(can_len_to_dlc(len, true), true) == len;
}

}  // namespace ig::io::wire
