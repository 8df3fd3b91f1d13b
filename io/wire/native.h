#pragma once
// Native IG pose datagram ("IGPS", version 1): fixed 128 bytes,
// little-endian, CRC-32 trailer. Layout and rules: docs/protocol.md.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "io/wire/pose_message.h"

namespace ig::io::wire {

inline constexpr std::size_t kNativeSize = 128;
inline constexpr std::uint16_t kNativeVersion = 1;
inline constexpr std::array<std::uint8_t, 4> kNativeMagic{'I', 'G', 'P', 'S'};

// Flag bits (u16 at offset 6): the content flags of pose_message.h.
inline constexpr std::uint16_t kNativeFlagGeodetic = kPoseFlagGeodetic;
inline constexpr std::uint16_t kNativeFlagRates = kPoseFlagRates;
inline constexpr std::uint16_t kNativeFlagVelocity = kPoseFlagVelocity;
inline constexpr std::uint16_t kNativeFlagSequence = kPoseFlagSequence;
inline constexpr std::uint16_t kNativeFlagSenderTime = kPoseFlagSenderTime;

// Field offsets (bytes).
namespace native_offset {
inline constexpr std::size_t kMagic = 0;
inline constexpr std::size_t kVersion = 4;
inline constexpr std::size_t kFlags = 6;
inline constexpr std::size_t kSequence = 8;
inline constexpr std::size_t kReserved0 = 12;
inline constexpr std::size_t kSenderTime = 16;
inline constexpr std::size_t kPosition = 24;      // 3 x f64
inline constexpr std::size_t kAttitude = 48;      // heading, pitch, roll f64
inline constexpr std::size_t kBodyRates = 72;     // roll, pitch, yaw rate f32
inline constexpr std::size_t kVelocity = 84;      // east, north, up f32
inline constexpr std::size_t kReserved1 = 96;     // 28 bytes
inline constexpr std::size_t kCrc = 124;          // u32 over [0, 124)
}  // namespace native_offset

// Encodes `pose` as-is (no validation; non-finite values go on the wire and
// the receiver rejects them). Rates / velocity / sequence / time are written
// only when their has_* flag is set, zeros otherwise. host_frame is not
// carried.
std::array<std::uint8_t, kNativeSize> encode_native(const PoseMessage& pose);

// Rejects: TooShort / TooLong (size != 128), BadMagic, BadVersion, BadCrc,
// NonFinite, OutOfRange. Never throws; reads only data[0, size).
DecodeResult decode_native(std::span<const std::uint8_t> data);

}  // namespace ig::io::wire
