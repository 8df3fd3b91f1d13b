#pragma once
// CIGI 3.3 subset: host -> IG datagrams (IG Control + Entity Control for the
// ownship, entity 0) and the IG -> host Start Of Frame. Byte order follows
// the sender (byte-swap magic 0x8000). Details: docs/protocol.md.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "io/wire/pose_message.h"

namespace ig::io::wire {

inline constexpr std::uint8_t kCigiOpIgControl = 1;
inline constexpr std::uint8_t kCigiOpEntityControl = 2;
inline constexpr std::uint8_t kCigiOpStartOfFrame = 101;
inline constexpr std::size_t kCigiIgControlSize = 24;
inline constexpr std::size_t kCigiEntityControlSize = 48;
inline constexpr std::size_t kCigiStartOfFrameSize = 24;
inline constexpr std::uint8_t kCigiMajorVersion = 3;
inline constexpr std::uint8_t kCigiMinorVersion = 3;  // 3.3, bits 4-7 of byte 5 / 4
inline constexpr std::uint16_t kCigiByteSwapMagic = 0x8000;
inline constexpr std::size_t kCigiMaxDatagram = 65535;
inline constexpr std::uint16_t kCigiOwnshipEntity = 0;

// IG mode values (2 bits).
inline constexpr std::uint32_t kCigiModeStandby = 0;
inline constexpr std::uint32_t kCigiModeOperate = 1;
inline constexpr std::uint32_t kCigiModeDebug = 2;

// IG Control (host frame, mode, timestamp if its valid bit is set) followed
// by one Entity Control for entity 0 built from `pose` (roll/pitch/yaw as
// f32 degrees; position x/y/z written as lat/lon/alt, so give a Geodetic
// pose). swap = write in the byte order opposite to this machine's.
// Timestamp = round(sender_time_s * 1e5) mod 2^32 (10 us units).
std::vector<std::uint8_t> encode_cigi_host_datagram(std::uint32_t host_frame, std::uint32_t ig_mode,
                                                    const PoseMessage& pose, bool swap);

// Decodes a host -> IG datagram. Rejects: TooShort (< 24), TooLong
// (> 65535), UnknownPacket (first packet not IG Control), BadVersion (major
// != 3, or IG Control size != 24 as in CIGI 3.0/3.1), BadMagic (byte-swap
// word neither 0x8000 nor 0x0080), Truncated (a packet header or body runs
// past the end, size 0, or an Entity Control whose size != 48), NoPose (no
// detached Entity Control for entity 0; host_frame / ig_mode still set),
// NonFinite / OutOfRange (the ownship values). The last entity-0 packet in
// the datagram wins. pose.sequence = pose.host_frame = host frame counter.
DecodeResult decode_cigi_host_datagram(std::span<const std::uint8_t> data);

// Start Of Frame (IG -> host, opcode 101, 24 bytes):
// [2] major version 3, [3] database number 0, [4] IG status,
// [5] bits 0-1 IG mode, bit 2 timestamp valid (set), bit 3 earth reference
// model (0 = WGS 84), bits 4-7 minor version (3); [6] magic 0x8000,
// [8] IG frame counter, [12] timestamp (10 us units), [16] last host frame.
std::array<std::uint8_t, kCigiStartOfFrameSize> encode_cigi_start_of_frame(
    std::uint32_t ig_frame, std::uint32_t last_host_frame, std::uint32_t timestamp_10us,
    std::uint32_t ig_mode, bool swap, std::uint8_t ig_status = 0);

struct CigiStartOfFrame {
  std::uint32_t ig_frame = 0;
  std::uint32_t last_host_frame = 0;
  std::uint32_t timestamp_10us = 0;
  std::uint32_t ig_mode = 0;
  std::uint8_t ig_status = 0;
  std::uint8_t minor_version = 0;
  bool timestamp_valid = false;
  bool byte_swapped = false;
};

struct StartOfFrameResult {
  std::optional<CigiStartOfFrame> sof;
  std::optional<Reject> reject;
};

// Decodes the first packet of an IG -> host datagram as Start Of Frame
// (further packets are ignored). Rejects: TooShort, TooLong, UnknownPacket
// (opcode != 101), Truncated (size != 24), BadVersion, BadMagic.
StartOfFrameResult decode_cigi_start_of_frame(std::span<const std::uint8_t> data);

}  // namespace ig::io::wire
