#pragma once
// One host -> IG CIGI datagram, decoded once: the framing and IG Control,
// the ownship pose and every packet the IG acts on, grouped by the part of
// the IG that takes them (pose intake, views, host services, environment,
// entities). The live loop decodes each datagram with decode_cigi and hands
// each part its group; nothing decodes the bytes again.

#include <cstdint>
#include <optional>
#include <span>

#include "io/wire/cigi_entities.h"
#include "io/wire/cigi_environment.h"
#include "io/wire/cigi_queries.h"
#include "io/wire/cigi_views.h"
#include "io/wire/pose_message.h"

namespace ig::io::wire {

struct CigiHostDatagram {
  // The ownship (entity 0, detached) and the IG Control's frame, mode and
  // timestamp; the reject reason of a datagram that carries no usable pose.
  DecodeResult ownship;
  CigiRequests requests;        // HAT/HOT and LOS requests
  CigiViewPackets views;        // View Control, View Definition
  CigiHostPackets host;         // rates, sky, atmosphere, weather, segments, position and conditions requests
  CigiEntityPackets entities;   // Entity Control (every id), Articulated Part Control

  // True when the datagram opened with a usable IG Control (the groups are
  // filled); false when the framing was refused (ownship.reject says why).
  bool framed() const { return host.ig_mode.has_value(); }
};

// Framing refused (size, first packet, version, magic): only
// ownship.reject is set. Otherwise every packet is taken by its group; a
// packet that cannot be framed (size 0 or past the end) ends the walk with
// a Truncated reject in its group and for the ownship.
CigiHostDatagram decode_cigi(std::span<const std::uint8_t> datagram, const CigiRequestLimits& limits = {});

}  // namespace ig::io::wire
