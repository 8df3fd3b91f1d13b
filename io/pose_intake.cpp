#include "io/pose_intake.h"

#include "io/pose.h"
#include "io/wire/cigi.h"
#include "io/wire/cigi_host_datagram.h"
#include "io/wire/fgnetfdm.h"
#include "io/wire/native.h"

namespace ig::io {

const char* protocol_name(Protocol p) {
  switch (p) {
    case Protocol::Native: return "native";
    case Protocol::Cigi: return "cigi";
    case Protocol::FgNetFdm: return "fgfdm";
    case Protocol::CanAerospace: return "canaerospace";
    case Protocol::CanFd: return "canfd";
  }
  return "unknown";
}

PoseIntake::PoseIntake(PoseFilter& filter, GeodeticToLocal to_local)
    : filter_(filter), to_local_(std::move(to_local)) {}

std::uint64_t PoseIntake::total_ok() const {
  std::uint64_t n = 0;
  for (const auto& c : counters_) n += c.ok;
  return n;
}

std::uint64_t PoseIntake::total_bad() const {
  std::uint64_t n = 0;
  for (const auto& c : counters_) n += c.bad;
  return n;
}

void PoseIntake::reject(Protocol p, const std::string& reason) {
  auto& c = counters_[int(p)];
  ++c.bad;
  ++c.reasons[reason];
}

void PoseIntake::handle(Protocol protocol, std::span<const std::uint8_t> datagram, double receive_time_s) {
  wire::DecodeResult r;
  switch (protocol) {
    case Protocol::Native: r = wire::decode_native(datagram); break;
    case Protocol::Cigi: handle_cigi(wire::decode_cigi(datagram), receive_time_s); return;
    case Protocol::FgNetFdm: r = wire::decode_fgnetfdm(datagram); break;
    case Protocol::CanAerospace:
    case Protocol::CanFd: reject(protocol, "not-a-datagram-protocol"); return;
  }
  finish(protocol, r, receive_time_s);
}

void PoseIntake::handle_cigi(const wire::CigiHostDatagram& d, double receive_time_s) {
  wire::DecodeResult r = d.ownship;
  if (r.host_frame) {
    last_host_frame_ = r.host_frame;
    ++ig_controls_;
    for (const auto& rc : d.host.rates) {
      if (rc.entity != wire::kCigiOwnshipEntity || rc.apply_to_part) continue;
      const bool zero = rc.velocity_mps == glm::dvec3(0.0) && rc.rates_dps == glm::dvec3(0.0);
      cigi_rates_ = zero ? std::nullopt : std::optional(rc);
    }
    if (r.pose && cigi_rates_) {
      // World rates are north, east, down; body rates forward, right, down.
      const glm::dvec3 v = cigi_rates_->velocity_mps;
      const glm::dquat q = attitude_from_hpr({r.pose->heading_deg, r.pose->pitch_deg, r.pose->roll_deg});
      r.pose->velocity_mps = cigi_rates_->body_axes ? forward_of(q) * v.x + right_of(q) * v.y - up_of(q) * v.z
                                                    : glm::dvec3(v.y, v.x, -v.z);
      r.pose->body_rates_dps = cigi_rates_->rates_dps;
      r.pose->has_velocity = r.pose->has_rates = true;
    }
  }
  finish(Protocol::Cigi, r, receive_time_s);
}

void PoseIntake::finish(Protocol protocol, const wire::DecodeResult& r, double receive_time_s) {
  if (!r.pose) {
    if (r.reject == wire::Reject::NoPose) {
      ++counters_[int(protocol)].no_pose;
      return;
    }
    reject(protocol, r.reject ? wire::reject_name(*r.reject) : "unknown");
    return;
  }
  handle_pose(protocol, *r.pose, receive_time_s);
}

void PoseIntake::handle_pose(Protocol protocol, const wire::PoseMessage& m, double receive_time_s) {
  PoseSample s;
  s.receive_time_s = receive_time_s;
  if (m.has_sender_time) s.sender_time_s = m.sender_time_s;
  if (m.has_sequence) s.sequence = m.sequence;
  if (m.frame == wire::PoseMessage::Frame::Geodetic) {
    const auto local = to_local_ ? to_local_(m.position.x, m.position.y, m.position.z) : std::nullopt;
    if (!local) {
      reject(protocol, "geodetic-without-georeference");
      return;
    }
    s.position = *local;
  } else {
    s.position = m.position;
  }
  s.attitude = attitude_from_hpr({m.heading_deg, m.pitch_deg, m.roll_deg});
  if (m.has_velocity) s.velocity_mps = m.velocity_mps;
  if (m.has_rates) s.body_rates_dps = m.body_rates_dps;
  s.source = protocol_name(protocol);
  filter_.push(s);
  ++counters_[int(protocol)].ok;
  last_source_ = s.source;
}

}  // namespace ig::io
