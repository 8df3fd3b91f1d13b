#pragma once
// Wire-level pose messages: the one decoded shape shared by every pose
// protocol the IG accepts (native IGPS, CIGI 3.3, FlightGear FGNetFDM), the
// reasons a datagram is rejected, and the validation every decoder applies.
//
// Pure data: no sockets, no GL. Conventions follow io/pose.h:
//   heading 0 = north, clockwise positive, [0, 360)
//   pitch nose-up positive, [-90, 90]
//   roll right-wing-down positive, (-180, 180]
//   local positions and velocities are ENU (x east, y north, z up).

#include <cstddef>
#include <cstdint>
#include <optional>

#include <glm/vec3.hpp>

namespace ig::io::wire {

struct PoseMessage {
  enum class Frame { Local, Geodetic };
  Frame frame = Frame::Local;
  // Local: ENU metres. Geodetic: x = latitude deg, y = longitude deg,
  // z = altitude m (above the ellipsoid / MSL as the sender defines it).
  glm::dvec3 position{0.0};
  double heading_deg = 0.0;
  double pitch_deg = 0.0;
  double roll_deg = 0.0;
  // x = roll rate, y = pitch rate, z = yaw rate, deg/s, signs matching the
  // angles (roll rate + = rolling right wing down, pitch rate + = nose going
  // up, yaw rate + = heading increasing, i.e. turning right). FGNetFDM gives
  // Euler-angle rates (phidot, thetadot, psidot), which equal body rates only
  // at wings-level attitude; the native protocol carries whatever the sender
  // put there (documented as body rates p, q, r).
  glm::dvec3 body_rates_dps{0.0};
  glm::dvec3 velocity_mps{0.0};  // ENU: x east, y north, z up
  bool has_rates = false;
  bool has_velocity = false;
  std::uint32_t sequence = 0;
  bool has_sequence = false;
  double sender_time_s = 0.0;
  bool has_sender_time = false;
  std::uint32_t host_frame = 0;  // CIGI host frame counter (also sequence)
};

enum class Reject {
  TooShort,       // buffer shorter than the fixed / minimum size
  TooLong,        // buffer longer than the fixed / maximum size
  BadMagic,       // magic / byte-swap word not recognised
  BadVersion,     // protocol version not supported
  BadCrc,         // native CRC-32 mismatch
  NonFinite,      // NaN or Inf in a field that is used
  OutOfRange,     // finite but outside the accepted range
  UnknownPacket,  // CIGI: first packet is not IG Control (or SOF expected)
  Truncated,      // CIGI: packet size 0, running past the datagram, or wrong
                  // for a known opcode
  NoPose,         // CIGI: valid datagram without an ownship Entity Control
};

const char* reject_name(Reject r);

struct DecodeResult {
  std::optional<PoseMessage> pose;
  std::optional<Reject> reject;
  // CIGI only: from the IG Control packet, reported even with NoPose.
  std::optional<std::uint32_t> host_frame;
  std::optional<std::uint32_t> ig_mode;
  bool byte_swapped = false;  // CIGI: sender byte order differs from ours

  bool ok() const { return pose.has_value(); }
};

// Accepted ranges (before normalisation).
inline constexpr double kMaxAbsAngleDeg = 1.0e4;
inline constexpr double kMaxAbsLocalXY = 1.0e8;
inline constexpr double kMaxAbsLocalZ = 1.0e6;
inline constexpr double kMaxAbsAltitude = 1.0e6;
inline constexpr double kMaxAbsRateDps = 1.0e5;
inline constexpr double kMaxAbsVelocity = 1.0e5;
inline constexpr double kMaxAbsSenderTime = 1.0e12;

// Checks a freshly decoded pose and normalises it in place:
//  * every used value finite (else NonFinite), within the ranges above and
//    lat in [-90, 90], lon in [-180, 360) (else OutOfRange);
//  * unused rates / velocity / time are zeroed;
//  * attitude folded to heading [0, 360), pitch [-90, 90], roll (-180, 180]
//    (a pitch beyond +-90 becomes the equivalent attitude with heading and
//    roll turned by 180); longitude folded to [-180, 180).
std::optional<Reject> validate_and_normalize(PoseMessage& pose);

// Decoder building blocks (one place for the common steps):
// a rejection, the size check of a fixed-size datagram, and the end of a
// decode (validate_and_normalize, then the pose or its reject).
DecodeResult rejected(Reject why);
std::optional<Reject> fixed_size_reject(std::size_t size, std::size_t expected);
DecodeResult finish_decode(PoseMessage pose, DecodeResult r = {});

// The content flags the native and CAN FD pose formats share (each names
// them its own way): which frame, and which optional fields the datagram
// carries. Unknown bits are ignored on decode.
inline constexpr std::uint16_t kPoseFlagGeodetic = 1u << 0;
inline constexpr std::uint16_t kPoseFlagRates = 1u << 1;
inline constexpr std::uint16_t kPoseFlagVelocity = 1u << 2;
inline constexpr std::uint16_t kPoseFlagSequence = 1u << 3;
inline constexpr std::uint16_t kPoseFlagSenderTime = 1u << 4;
std::uint16_t pose_content_flags(const PoseMessage& pose);
void apply_pose_content_flags(std::uint16_t flags, PoseMessage& pose);

// True when `pose` is what a decoder may return (finite, in normalised
// ranges). Used by the tests and fuzz targets.
bool is_valid_output(const PoseMessage& pose);

// Angle helpers: [0, 360) and (-180, 180].
double wrap_360(double deg);
double wrap_180(double deg);

}  // namespace ig::io::wire
