#include "io/wire/cigi_host_datagram.h"

#include "io/wire/byte_io.h"
#include "io/wire/cigi.h"
#include "io/wire/cigi_byte_order.h"
#include "io/wire/cigi_packet_steps.h"

namespace ig::io::wire {

using bytes::Order;

namespace {

constexpr std::uint8_t kTimestampValid = 1u << 2;  // IG Control [4] bit 2
constexpr std::uint8_t kEntityAttached = 1u << 2;  // Entity Control [4] bit 2

// The ownship pose from its Entity Control and the IG Control's frame and
// timestamp, validated as every pose decoder does.
DecodeResult ownship_pose(const std::uint8_t* ec, const std::uint8_t* ig, Order o, DecodeResult r) {
  PoseMessage m;
  m.frame = PoseMessage::Frame::Geodetic;
  m.roll_deg = bytes::load_f32(ec + 12, o);
  m.pitch_deg = bytes::load_f32(ec + 16, o);
  m.heading_deg = bytes::load_f32(ec + 20, o);
  m.position = {bytes::load_f64(ec + 24, o), bytes::load_f64(ec + 32, o), bytes::load_f64(ec + 40, o)};
  m.host_frame = m.sequence = *r.host_frame;
  m.has_sequence = true;
  if (ig[4] & kTimestampValid) {
    m.sender_time_s = static_cast<double>(bytes::load_u32(ig + 12, o)) * 1e-5;
    m.has_sender_time = true;
  }
  return finish_decode(m, r);
}

}  // namespace

CigiHostDatagram decode_cigi(std::span<const std::uint8_t> data, const CigiRequestLimits& limits) {
  CigiHostDatagram d;
  DecodeResult& r = d.ownship;
  // A wrong IG Control size reads as another CIGI version's packet.
  const auto order = cigi_check_first_packet(data, kCigiOpIgControl, kCigiIgControlSize, Reject::BadVersion, r.reject);
  if (!order) return d;
  const Order o = *order;
  const std::uint8_t* ig = data.data();
  r.byte_swapped = d.requests.byte_swapped = (o != bytes::kHostOrder);
  r.host_frame = d.requests.host_frame = bytes::load_u32(ig + 8, o);
  r.ig_mode = ig[4] & 0x3u;
  d.host.ig_mode = std::uint8_t(ig[4] & 0x3u);
  if (const auto database = std::int8_t(ig[3]); database != 0) d.host.database = database;

  const std::uint8_t* ownship = nullptr;  // the last detached entity-0 Entity Control wins
  bool entity_wrong_size = false;
  auto on_packet = [&](std::uint8_t op, const std::uint8_t* q, std::size_t size) {
    if (steps::is_entity_op(op)) {
      steps::take_entity(op, q, size, o, d.entities);
      if (op == kCigiOpEntityControl) {
        if (size != kCigiEntityControlSize) entity_wrong_size = true;
        else if (bytes::load_u16(q + 2, o) == kCigiOwnshipEntity && (q[4] & kEntityAttached) == 0) ownship = q;
      }
    } else if (steps::is_request_op(op)) {
      steps::take_request(op, q, size, o, limits, d.requests);
    } else if (steps::is_view_op(op)) {
      steps::take_view(op, q, size, o, d.views);
    } else if (steps::is_host_op(op)) {
      steps::take_host(op, q, size, o, d.host);
    } else if (op != kCigiOpIgControl) {
      d.host.unsupported.push_back(op);  // IG Control repeats are skipped by their size
    }
  };
  bool truncated = false;
  for_each_cigi_host_packet(data, on_packet, [&](std::uint8_t op) {
    truncated = true;
    if (steps::is_entity_op(op)) d.entities.rejects.push_back(QueryReject::Truncated);
    else if (steps::is_request_op(op)) d.requests.rejects.push_back(QueryReject::Truncated);
    else if (steps::is_view_op(op)) d.views.rejects.push_back(QueryReject::Truncated);
    else if (steps::is_host_op(op)) d.host.rejects.push_back(QueryReject::Truncated);
  });
  if (truncated || entity_wrong_size) r.reject = Reject::Truncated;
  else if (!ownship) r.reject = Reject::NoPose;
  else r = ownship_pose(ownship, ig, o, r);
  return d;
}

}  // namespace ig::io::wire
