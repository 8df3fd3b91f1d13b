#include "io/pose_stream.h"

#include <algorithm>

#include "io/wire/cigi.h"
#include "io/wire/fgnetfdm.h"
#include "io/wire/native.h"

namespace ig::io {

wire::PoseMessage path_pose_message(const PathInterpolator& path, double t, double h, std::uint32_t sequence,
                                    Pose& pose, Hpr& hpr) {
  pose = path.sample(t);
  const glm::dvec3 velocity =
      (path.sample(t + h).position - path.sample(std::max(0.0, t - h)).position) / (t >= h ? 2 * h : h);
  hpr = hpr_from_attitude(pose.attitude);
  wire::PoseMessage m;
  m.heading_deg = hpr.heading_deg;
  m.pitch_deg = hpr.pitch_deg;
  m.roll_deg = hpr.roll_deg;
  m.sequence = sequence;
  m.has_sequence = true;
  m.velocity_mps = velocity;
  m.has_velocity = true;
  m.position = pose.position;
  return m;
}

std::vector<std::uint8_t> encode_pose_datagram(Protocol protocol, const wire::PoseMessage& m,
                                               std::uint32_t host_frame) {
  switch (protocol) {
    case Protocol::Native: {
      const auto a = wire::encode_native(m);
      return {a.begin(), a.end()};
    }
    case Protocol::Cigi: return wire::encode_cigi_host_datagram(host_frame, wire::kCigiModeOperate, m, false);
    case Protocol::FgNetFdm: {
      const auto a = wire::encode_fgnetfdm(m);
      return {a.begin(), a.end()};
    }
    default: return {};  // CAN formats: frames, not datagrams
  }
}

}  // namespace ig::io
