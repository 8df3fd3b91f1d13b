#include "io/wire/pose_message.h"

#include <cmath>

namespace ig::io::wire {

const char* reject_name(Reject r) {
  switch (r) {
    case Reject::TooShort: return "TooShort";
    case Reject::TooLong: return "TooLong";
    case Reject::BadMagic: return "BadMagic";
    case Reject::BadVersion: return "BadVersion";
    case Reject::BadCrc: return "BadCrc";
    case Reject::NonFinite: return "NonFinite";
    case Reject::OutOfRange: return "OutOfRange";
    case Reject::UnknownPacket: return "UnknownPacket";
    case Reject::Truncated: return "Truncated";
    case Reject::NoPose: return "NoPose";
  }
  return "Unknown";
}

double wrap_360(double deg) {
  double r = std::fmod(deg, 360.0);
  if (r < 0.0) r += 360.0;
  if (r >= 360.0) r -= 360.0;  // -tiny + 360 rounds to 360
  return r;
}

double wrap_180(double deg) {
  if (deg > -180.0 && deg <= 180.0) return deg;  // keep in-range values bit-exact
  double r = std::fmod(deg, 360.0);              // exact, (-360, 360)
  if (r > 180.0) {
    r -= 360.0;  // exact (Sterbenz)
  } else if (r <= -180.0) {
    r += 360.0;
  }
  return r;
}

namespace {

bool finite3(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool within3(const glm::dvec3& v, double lim) {
  return std::fabs(v.x) <= lim && std::fabs(v.y) <= lim && std::fabs(v.z) <= lim;
}

}  // namespace

std::optional<Reject> validate_and_normalize(PoseMessage& p) {
  if (!p.has_rates) p.body_rates_dps = glm::dvec3(0.0);
  if (!p.has_velocity) p.velocity_mps = glm::dvec3(0.0);
  if (!p.has_sender_time) p.sender_time_s = 0.0;

  // Finiteness first so NaN is reported as NonFinite, not OutOfRange.
  if (!finite3(p.position) || !std::isfinite(p.heading_deg) || !std::isfinite(p.pitch_deg) ||
      !std::isfinite(p.roll_deg) || !finite3(p.body_rates_dps) || !finite3(p.velocity_mps) ||
      !std::isfinite(p.sender_time_s)) {
    return Reject::NonFinite;
  }

  if (p.frame == PoseMessage::Frame::Geodetic) {
    const double lat = p.position.x, lon = p.position.y, alt = p.position.z;
    if (!(lat >= -90.0 && lat <= 90.0)) return Reject::OutOfRange;
    if (!(lon >= -180.0 && lon < 360.0)) return Reject::OutOfRange;
    if (!(std::fabs(alt) < kMaxAbsAltitude)) return Reject::OutOfRange;
  } else if (p.frame == PoseMessage::Frame::Local) {
    if (!(std::fabs(p.position.x) < kMaxAbsLocalXY) || !(std::fabs(p.position.y) < kMaxAbsLocalXY) ||
        !(std::fabs(p.position.z) < kMaxAbsLocalZ)) {
      return Reject::OutOfRange;
    }
  } else {
    return Reject::OutOfRange;
  }
  if (!(std::fabs(p.heading_deg) <= kMaxAbsAngleDeg) || !(std::fabs(p.pitch_deg) <= kMaxAbsAngleDeg) ||
      !(std::fabs(p.roll_deg) <= kMaxAbsAngleDeg)) {
    return Reject::OutOfRange;
  }
  if (!within3(p.body_rates_dps, kMaxAbsRateDps) || !within3(p.velocity_mps, kMaxAbsVelocity) ||
      !(std::fabs(p.sender_time_s) <= kMaxAbsSenderTime)) {
    return Reject::OutOfRange;
  }

  // Normalise the attitude; pitch past the pole flips heading and roll.
  double heading = p.heading_deg, roll = p.roll_deg;
  double pitch = wrap_180(p.pitch_deg);
  if (pitch > 90.0) {
    pitch = 180.0 - pitch;
    heading += 180.0;
    roll += 180.0;
  } else if (pitch < -90.0) {
    pitch = -180.0 - pitch;
    heading += 180.0;
    roll += 180.0;
  }
  p.heading_deg = wrap_360(heading);
  p.pitch_deg = pitch;
  p.roll_deg = wrap_180(roll);
  if (p.frame == PoseMessage::Frame::Geodetic) {
    double lon = p.position.y;
    if (lon >= 180.0) lon -= 360.0;  // [-180, 360) -> [-180, 180), exact
    p.position.y = lon;
  }
  return std::nullopt;
}

bool is_valid_output(const PoseMessage& p) {
  if (!finite3(p.position) || !std::isfinite(p.heading_deg) || !std::isfinite(p.pitch_deg) ||
      !std::isfinite(p.roll_deg) || !finite3(p.body_rates_dps) || !finite3(p.velocity_mps) ||
      !std::isfinite(p.sender_time_s)) {
    return false;
  }
  if (p.frame == PoseMessage::Frame::Geodetic) {
    if (!(p.position.x >= -90.0 && p.position.x <= 90.0)) return false;
    if (!(p.position.y >= -180.0 && p.position.y < 180.0)) return false;
    if (!(std::fabs(p.position.z) < kMaxAbsAltitude)) return false;
  } else if (p.frame == PoseMessage::Frame::Local) {
    if (!(std::fabs(p.position.x) < kMaxAbsLocalXY) || !(std::fabs(p.position.y) < kMaxAbsLocalXY) ||
        !(std::fabs(p.position.z) < kMaxAbsLocalZ)) {
      return false;
    }
  } else {
    return false;
  }
  if (!(p.heading_deg >= 0.0 && p.heading_deg < 360.0)) return false;
  if (!(p.pitch_deg >= -90.0 && p.pitch_deg <= 90.0)) return false;
  if (!(p.roll_deg > -180.0 && p.roll_deg <= 180.0)) return false;
  if (!within3(p.body_rates_dps, kMaxAbsRateDps) || !within3(p.velocity_mps, kMaxAbsVelocity)) return false;
  if (!(std::fabs(p.sender_time_s) <= kMaxAbsSenderTime)) return false;
  return true;
}

DecodeResult rejected(Reject why) {
  DecodeResult r;
  r.reject = why;
  return r;
}

std::optional<Reject> fixed_size_reject(std::size_t size, std::size_t expected) {
  if (size < expected) return Reject::TooShort;
  if (size > expected) return Reject::TooLong;
  return std::nullopt;
}

std::uint16_t pose_content_flags(const PoseMessage& pose) {
  std::uint16_t flags = 0;
  if (pose.frame == PoseMessage::Frame::Geodetic) flags |= kPoseFlagGeodetic;
  if (pose.has_rates) flags |= kPoseFlagRates;
  if (pose.has_velocity) flags |= kPoseFlagVelocity;
  if (pose.has_sequence) flags |= kPoseFlagSequence;
  if (pose.has_sender_time) flags |= kPoseFlagSenderTime;
  return flags;
}

void apply_pose_content_flags(std::uint16_t flags, PoseMessage& pose) {
  pose.frame = (flags & kPoseFlagGeodetic) ? PoseMessage::Frame::Geodetic : PoseMessage::Frame::Local;
  pose.has_rates = (flags & kPoseFlagRates) != 0;
  pose.has_velocity = (flags & kPoseFlagVelocity) != 0;
  pose.has_sequence = (flags & kPoseFlagSequence) != 0;
  pose.has_sender_time = (flags & kPoseFlagSenderTime) != 0;
}

DecodeResult finish_decode(PoseMessage pose, DecodeResult r) {
  if (auto why = validate_and_normalize(pose)) {
    r.reject = *why;
    return r;
  }
  r.pose = pose;
  return r;
}

}  // namespace ig::io::wire
