#pragma once
// FlightGear native FDM packet (FGNetFDM, version 24): 408 bytes,
// big-endian (doubles as big-endian 8-byte values). Sent by
//   fgfs --native-fdm=socket,out,60,HOST,PORT,udp
// Fields used: docs/protocol.md.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "io/wire/pose_message.h"

namespace ig::io::wire {

inline constexpr std::size_t kFgNetFdmSize = 408;
inline constexpr std::uint32_t kFgNetFdmVersion = 24;

namespace fgfdm_offset {
inline constexpr std::size_t kVersion = 0;     // u32
inline constexpr std::size_t kLongitude = 8;   // f64 rad
inline constexpr std::size_t kLatitude = 16;   // f64 rad
inline constexpr std::size_t kAltitude = 24;   // f64 m
inline constexpr std::size_t kAgl = 32;        // f32 m
inline constexpr std::size_t kPhi = 36;        // f32 rad, roll
inline constexpr std::size_t kTheta = 40;      // f32 rad, pitch
inline constexpr std::size_t kPsi = 44;        // f32 rad, true heading
inline constexpr std::size_t kAlpha = 48;      // f32 rad
inline constexpr std::size_t kBeta = 52;       // f32 rad
inline constexpr std::size_t kPhiDot = 56;     // f32 rad/s
inline constexpr std::size_t kThetaDot = 60;   // f32 rad/s
inline constexpr std::size_t kPsiDot = 64;     // f32 rad/s
inline constexpr std::size_t kVcas = 68;       // f32 kt
inline constexpr std::size_t kClimbRate = 72;  // f32 ft/s
inline constexpr std::size_t kVNorth = 76;     // f32 ft/s
inline constexpr std::size_t kVEast = 80;      // f32 ft/s
inline constexpr std::size_t kVDown = 84;      // f32 ft/s
inline constexpr std::size_t kCurTime = 356;   // u32 unix seconds
inline constexpr std::size_t kVisibility = 364;  // f32 m
}  // namespace fgfdm_offset

// Encodes a Geodetic pose (lat/lon deg -> rad, attitude deg -> rad, Euler
// rates from body_rates_dps when has_rates, NED ft/s velocity from the ENU
// velocity when has_velocity, vcas and climb rate derived from it). Every
// other field is zero (no engines, tanks or wheels) except visibility
// (10 km) and cur_time (sender_time_s truncated to whole seconds).
std::array<std::uint8_t, kFgNetFdmSize> encode_fgnetfdm(const PoseMessage& pose);

// Rejects: TooShort / TooLong (size != 408), BadVersion (version != 24),
// NonFinite, OutOfRange. The result is Geodetic with has_rates (Euler rates
// phidot, thetadot, psidot in deg/s) and has_velocity (ENU m/s) set; no
// sequence or sender time (FGNetFDM has only whole-second cur_time).
DecodeResult decode_fgnetfdm(std::span<const std::uint8_t> data);

}  // namespace ig::io::wire
