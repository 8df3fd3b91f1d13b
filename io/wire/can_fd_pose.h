#pragma once
// CAN FD single-frame full pose ("IF" version 1): one 64-byte CAN FD frame on
// a project-defined 11-bit id carrying the content of the native UDP pose
// (io/wire/native.h) in a compacted form, little-endian, CRC-32 trailer.
// Layout and resolutions: docs/can.md.

#include <cstddef>
#include <cstdint>

#include "io/wire/can_frame.h"
#include "io/wire/pose_message.h"

namespace ig::io::wire {

inline constexpr std::uint32_t kCanFdPoseId = 0x7E0;  // project-defined
inline constexpr std::size_t kCanFdPoseSize = 64;
inline constexpr std::uint8_t kCanFdPoseMagic0 = 'I';
inline constexpr std::uint8_t kCanFdPoseMagic1 = 'F';
inline constexpr std::uint8_t kCanFdPoseVersion = 1;

// Flag bits (u8 at offset 3): same meaning as the native kNativeFlag* bits.
inline constexpr std::uint8_t kCanFdFlagGeodetic = kPoseFlagGeodetic;
inline constexpr std::uint8_t kCanFdFlagRates = kPoseFlagRates;
inline constexpr std::uint8_t kCanFdFlagVelocity = kPoseFlagVelocity;
inline constexpr std::uint8_t kCanFdFlagSequence = kPoseFlagSequence;
inline constexpr std::uint8_t kCanFdFlagSenderTime = kPoseFlagSenderTime;

// Rates and velocity are scaled i16: value = raw * scale. +-32767 is the
// saturated end of the range; -32768 marks a value that was not finite (the
// receiver rejects it as NonFinite).
inline constexpr double kCanFdRateScale = 0.02;     // deg/s per count, +-655.34
inline constexpr double kCanFdVelocityScale = 0.05; // m/s per count, +-1638.35
inline constexpr std::int16_t kCanFdI16NonFinite = -32768;

namespace can_fd_offset {
inline constexpr std::size_t kMagic = 0;       // 'I' 'F'
inline constexpr std::size_t kVersion = 2;     // u8
inline constexpr std::size_t kFlags = 3;       // u8
inline constexpr std::size_t kSequence = 4;    // u32
inline constexpr std::size_t kSenderTime = 8;  // f64 s
inline constexpr std::size_t kPositionXY = 16; // 2 x f64: lat, lon deg / east, north m
inline constexpr std::size_t kPositionZ = 32;  // f32: altitude / up m
inline constexpr std::size_t kAttitude = 36;   // heading, pitch, roll f32 deg
inline constexpr std::size_t kBodyRates = 48;  // roll, pitch, yaw rate i16 x 0.02 deg/s
inline constexpr std::size_t kVelocity = 54;   // east, north, up i16 x 0.05 m/s
inline constexpr std::size_t kCrc = 60;        // u32 CRC-32 over [0, 60)
}  // namespace can_fd_offset

// Encodes `pose` as-is into an FD frame (id kCanFdPoseId, len 64, FD + BRS
// flags). Rates / velocity / sequence / time only when their has_* flag is
// set, zeros otherwise; out-of-range rates / velocities saturate; NaN goes on
// the wire (f32 / f64 fields, the i16 marker) and the receiver rejects it.
CanFrame encode_can_fd_pose(const PoseMessage& pose);

// Rejects: UnknownPacket (id != kCanFdPoseId, or an extended / RTR / error
// frame), TooShort (not an FD frame, or len < 64), TooLong (len > 64),
// BadMagic, BadVersion, BadCrc, NonFinite, OutOfRange (validate_and_normalize).
DecodeResult decode_can_fd_pose(const CanFrame& frame);

}  // namespace ig::io::wire
