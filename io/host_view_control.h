#pragma once
// CIGI View Control / View Definition from the host applied to the IG's
// channels: the same ChannelSpec fields a config file sets (view offsets,
// vertical field of view), so a channel set up by the host renders as one set
// up by the config, plus the entity the view rides on and the eye's offset
// from it (chase, tower, wingman views). What a ChannelSpec cannot hold is
// counted, not guessed.
// docs/host-services.md, "View control".

#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "io/scenario.h"
#include "io/wire/cigi_views.h"

namespace ig::io {

// Applies one packet; returns "" when applied in full, else why not (in
// part): "orthographic-ignored" (not applied), "asymmetric-frustum" (drawn symmetric
// with the same vertical extent), "frustum-part-ignored" (near, far, left,
// right or mirror: the render settings and the image aspect keep those).
std::string apply_view_control(ChannelSpec& channel, const wire::CigiViewControl& v);
std::string apply_view_definition(ChannelSpec& channel, const wire::CigiViewDefinition& v);

class HostViewControl {
 public:
  // view id -> that channel's settings, nullptr when there is none.
  using ChannelLookup = std::function<ChannelSpec*(std::uint16_t view)>;
  // Every CIGI datagram: its view packets applied in order.
  void take(const wire::CigiViewPackets& packets, const ChannelLookup& channels);
  void take(std::span<const std::uint8_t> datagram, const ChannelLookup& channels);  // decodes, then the above
  std::uint64_t applied() const { return applied_; }
  const std::map<std::string, std::uint64_t>& notes() const { return notes_; }
  nlohmann::json summary() const { return {{"applied", applied_}, {"notes", notes_}}; }

 private:
  std::uint64_t applied_ = 0;
  std::map<std::string, std::uint64_t> notes_;  // reason -> count (rejects and partial applications)
};

}  // namespace ig::io
