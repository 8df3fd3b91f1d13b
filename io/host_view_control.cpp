#include "io/host_view_control.h"

#include "io/wire/cigi.h"

#include <cmath>

namespace ig::io {

std::string apply_view_control(ChannelSpec& channel, const wire::CigiViewControl& v) {
  // The view rides on its entity (the renderer places it; an entity the IG
  // does not have leaves the view on the ownship).
  channel.entity = v.entity;
  // CIGI yaw / pitch / roll of the view relative to its entity = the config's offsets.
  if (v.yaw_deg) channel.heading_offset_deg = *v.yaw_deg;
  if (v.pitch_deg) channel.pitch_offset_deg = *v.pitch_deg;
  if (v.roll_deg) channel.roll_offset_deg = *v.roll_deg;
  if (v.x_m) channel.eye_offset_m[0] = *v.x_m;
  if (v.y_m) channel.eye_offset_m[1] = *v.y_m;
  if (v.z_m) channel.eye_offset_m[2] = *v.z_m;
  return "";
}

std::string apply_view_definition(ChannelSpec& channel, const wire::CigiViewDefinition& v) {
  if (v.orthographic) return "orthographic-ignored";
  std::string note;
  if (v.top_deg && v.bottom_deg) {
    channel.fov_y_deg = double(*v.top_deg) - double(*v.bottom_deg);
    if (std::abs(double(*v.top_deg) + double(*v.bottom_deg)) > 1e-4) note = "asymmetric-frustum";
  } else if (v.top_deg || v.bottom_deg) {
    channel.fov_y_deg = 2.0 * std::abs(double(v.top_deg ? *v.top_deg : *v.bottom_deg));
  }
  if (note.empty() && (v.near_m || v.far_m || v.left_deg || v.right_deg || v.mirror)) note = "frustum-part-ignored";
  return note;
}

void HostViewControl::take(std::span<const std::uint8_t> datagram, const ChannelLookup& channels) {
  take(wire::decode_cigi_view_packets(datagram), channels);
}

void HostViewControl::take(const wire::CigiViewPackets& packets, const ChannelLookup& channels) {
  for (wire::QueryReject r : packets.rejects) ++notes_[std::string("view-") + wire::query_reject_name(r)];
  auto apply = [&](const auto& packet, auto&& how) {
    ChannelSpec* spec = channels ? channels(packet.view) : nullptr;
    if (!spec) {
      ++notes_["view-unknown-channel"];
      return;
    }
    const std::string note = how(*spec, packet);
    if (!note.empty()) ++notes_[note];
    if (note != "orthographic-ignored") ++applied_;
  };
  for (const auto& c : packets.controls)
    apply(c, [](ChannelSpec& s, const wire::CigiViewControl& v) { return apply_view_control(s, v); });
  for (const auto& d : packets.definitions)
    apply(d, [](ChannelSpec& s, const wire::CigiViewDefinition& v) { return apply_view_definition(s, v); });
}

}  // namespace ig::io
