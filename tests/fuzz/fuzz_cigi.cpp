// libFuzzer target: CIGI 3.3 host datagram, host service request, view,
// environment and Start Of Frame / response decoders.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <variant>
#include <vector>

#include "fuzz_check.h"
#include "io/wire/cigi.h"
#include "io/wire/cigi_environment.h"
#include "io/wire/cigi_queries.h"
#include "io/wire/cigi_views.h"
#include "io/entities/entity_table.h"
#include "io/wire/cigi_entities.h"
#include "io/wire/cigi_host_datagram.h"
#include "environment/cloud_layers.h"

// The entity packets of `packet` behind the datagram's own IG Control.
template <class Packet>
ig::io::wire::CigiEntityPackets again_entities(std::span<const std::uint8_t> in, const Packet& packet) {
  std::vector<std::uint8_t> d(in.begin(), in.begin() + std::min<std::size_t>(in.size(), 24));
  d.insert(d.end(), packet.begin(), packet.end());
  return ig::io::wire::decode_cigi(d).entities;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ig::io::wire;
  const std::span<const std::uint8_t> in(data, size);
  const DecodeResult r = decode_cigi_host_datagram(in);
  ig_fuzz::check(r);
  if (r.reject == Reject::NoPose && (!r.host_frame || !r.ig_mode)) __builtin_trap();
  if (r.pose) {
    // An accepted ownship re-encodes (both byte orders) to an accepted datagram.
    for (bool swap : {false, true}) {
      const DecodeResult again =
          decode_cigi_host_datagram(encode_cigi_host_datagram(*r.host_frame, *r.ig_mode, *r.pose, swap));
      if (!again.pose) __builtin_trap();
    }
  }
  const StartOfFrameResult s = decode_cigi_start_of_frame(in);
  if (s.sof.has_value() == s.reject.has_value()) __builtin_trap();
  if (s.sof && s.sof->ig_mode > 3u) __builtin_trap();
  // Requests: only well-formed ones come out, each re-encodes to itself.
  const CigiRequests q = decode_cigi_requests(in);
  if (!q.host_frame && (!q.requests.empty() || !q.rejects.empty())) __builtin_trap();
  for (const CigiRequest& req : q.requests) {
    if (const auto* h = std::get_if<HatHotRequest>(&req)) {
      if (int(h->type) > 2 || !std::isfinite(h->point.x + h->point.y + h->point.z)) __builtin_trap();
    } else if (const auto* v = std::get_if<LosVectorRequest>(&req)) {
      if (!(v->min_range_m >= 0 && v->max_range_m >= v->min_range_m) || !std::isfinite(v->max_range_m)) __builtin_trap();
    }
  }
  (void)decode_cigi_responses(in);
  // View packets: enabled angles come out finite and bounded.
  for (const CigiViewDefinition& v : decode_cigi_view_packets(in).definitions)
    if ((v.top_deg && !(std::abs(*v.top_deg) <= 90.0f)) || (v.top_deg && v.bottom_deg && !(*v.top_deg > *v.bottom_deg)))
      __builtin_trap();
  // Environment packets: each one taken re-encodes, behind the datagram's
  // own IG Control (in its byte order), to the same packet.
  const CigiHostPackets h = decode_cigi_host_packets(in);
  const bool swap = in.size() >= 8 && in[6] == 0x80 ? std::endian::native == std::endian::little
                                                      : std::endian::native == std::endian::big;
  auto again = [&](const auto& packet) {
    std::vector<std::uint8_t> d(in.begin(), in.begin() + std::min<std::size_t>(in.size(), 24));
    d.insert(d.end(), packet.begin(), packet.end());
    return decode_cigi_host_packets(d);
  };
  for (const CigiCelestialSphere& c : h.celestial)
    if (c.hour > 23 || c.minute > 59 || again(encode_cigi_celestial(c, swap)).celestial.at(0) != c) __builtin_trap();
  for (const CigiAtmosphere& a : h.atmosphere)
    if (!(a.visibility_m >= 0.0f) || again(encode_cigi_atmosphere(a, swap)).atmosphere.at(0) != a) __builtin_trap();
  // Weather: re-encodes to itself; as a cloud layer, accepted only within
  // the documented ranges.
  for (const CigiWeatherControl& w : h.weather) {
    if (again(encode_cigi_weather(w, swap)).weather.at(0) != w) __builtin_trap();
    const auto layer = cigi_cloud_layer(w);
    if (!layer) continue;
    const auto check = ig::environment::check_cloud_layer(*layer, 0.0);
    if (check.layer && !(check.layer->coverage >= 0.0 && check.layer->coverage <= 1.0 && check.layer->thickness_m >= 0.0 &&
                         check.layer->base_m >= 0.0 && check.layer->base_m + check.layer->thickness_m <= 1e5 &&
                         check.layer->visibility_m > 0.0 && std::isfinite(check.layer->wind_mps.x)))
      __builtin_trap();
  }
  for (const CigiRateControl& rc : h.rates)
    if (again(encode_cigi_rate_control(rc, swap)).rates.at(0) != rc) __builtin_trap();
  for (const CigiCollisionSegment& sg : h.segments)
    if (again(encode_cigi_collision_segment(sg, swap)).segments.at(0) != sg) __builtin_trap();
  for (const CigiPositionRequest& pr : h.positions)
    if (again(encode_cigi_position_request(pr, swap)).positions.at(0) != pr) __builtin_trap();
  for (const std::uint8_t op : h.unsupported)
    if (cigi_opcode_supported(op)) __builtin_trap();
  // Entity packets: each one taken re-encodes to itself; the entity table
  // takes them all and places every entity at finite positions.
  const CigiHostDatagram whole = decode_cigi(in);
  for (const CigiEntityControl& e : whole.entities.controls)
    if (again_entities(in, encode_cigi_entity_control(e, swap)).controls.at(0) != e) __builtin_trap();
  for (const CigiArticulatedPart& a : whole.entities.parts)
    if (again_entities(in, encode_cigi_articulated_part(a, swap)).parts.at(0) != a) __builtin_trap();
  ig::io::EntityTable table([](double lat, double lon, double alt) { return glm::dvec3(lon * 1e5, lat * 1e5, alt); },
                            [](double, double) { return ig::io::SurfaceSample{100.0, {0.0, 0.0, 1.0}}; });
  table.take(whole.entities, whole.host.rates, 1.0);
  for (const auto& p : table.poses_at(2.0, ig::io::Pose{}))
    if (!std::isfinite(p.pose.position.x + p.pose.position.y + p.pose.position.z)) __builtin_trap();
  (void)decode_cigi_ig_packets(in);
  return 0;
}
