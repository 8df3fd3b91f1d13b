#include "io/wire/canaerospace.h"

#include <bit>
#include <cmath>

#include "io/wire/byte_io.h"

namespace ig::io::wire {

namespace {

using bytes::Order;

// Known ids, in the order of the per-id tables.
constexpr std::array<std::uint16_t, kCanAsKnownIdCount> kKnownIds{
    canas_id::kBodyPitchRate, canas_id::kBodyRollRate, canas_id::kBodyYawRate, canas_id::kBodyPitch,
    canas_id::kBodyRoll,      canas_id::kBaroAltitude, canas_id::kHeading,     canas_id::kStdAltitude,
    canas_id::kTrueAltitude,  canas_id::kLatitude,     canas_id::kLongitude};

bool is_position_id(std::uint32_t id) { return id == canas_id::kLatitude || id == canas_id::kLongitude; }

bool type_allowed(std::uint32_t id, std::uint8_t type) {
  if (type == kCanAsFloat) return true;
  return is_position_id(id) && (type == kCanAsDoubleH || type == kCanAsDoubleL);
}

}  // namespace

int canaerospace_id_index(std::uint32_t id) {
  for (int i = 0; i < kCanAsKnownIdCount; ++i) {
    if (kKnownIds[static_cast<std::size_t>(i)] == id) return i;
  }
  return -1;
}

bool canaerospace_is_altitude_id(std::uint16_t id) {
  return id == canas_id::kBaroAltitude || id == canas_id::kStdAltitude || id == canas_id::kTrueAltitude;
}

std::optional<CanAerospaceValue> decode_canaerospace(const CanFrame& frame, CanAerospaceStats& stats,
                                                     const CanAerospaceOptions& options) {
  ++stats.frames;
  auto reject = [&](CanAsReject why, std::uint64_t& counter) -> std::optional<CanAerospaceValue> {
    ++counter;
    stats.last_reject = why;
    return std::nullopt;
  };
  if ((frame.flags & (kCanFlagFd | kCanFlagExtended | kCanFlagRtr | kCanFlagError)) != 0) {
    return reject(CanAsReject::NotClassicFrame, stats.not_classic);
  }
  const int index = canaerospace_id_index(frame.id);
  if (index < 0) return reject(CanAsReject::UnknownId, stats.unknown_id);
  if (frame.len != 8) return reject(CanAsReject::WrongDlc, stats.wrong_dlc);
  const std::uint8_t* p = frame.data.data();
  CanAerospaceValue v;
  v.id = static_cast<std::uint16_t>(frame.id);
  v.node_id = p[0];
  v.data_type = p[1];
  v.service_code = p[2];
  v.message_code = p[3];
  v.raw = bytes::load_u32(p + 4, Order::Big);
  if (options.node_id && *options.node_id != v.node_id) return reject(CanAsReject::WrongNode, stats.wrong_node);
  if (!type_allowed(frame.id, v.data_type)) return reject(CanAsReject::WrongDataType, stats.wrong_type);
  if (v.data_type == kCanAsFloat) {
    v.value = std::bit_cast<float>(v.raw);
    if (!std::isfinite(v.value)) return reject(CanAsReject::NonFinite, stats.non_finite);
  }
  ++stats.accepted;
  // Continuity: DOUBLEL halves have their own counter (they repeat the
  // DOUBLEH's code).
  const std::size_t slot = static_cast<std::size_t>(index) * 2 + (v.data_type == kCanAsDoubleL ? 1 : 0);
  std::int16_t& last = stats.last_code[slot];
  if (last >= 0 && v.message_code != static_cast<std::uint8_t>(last + 1)) ++stats.code_gaps;
  last = v.message_code;
  return v;
}

CanFrame make_canaerospace_frame(std::uint16_t id, std::uint8_t node_id, std::uint8_t data_type,
                                 std::uint8_t service_code, std::uint8_t message_code, std::uint32_t raw) {
  CanFrame f;
  f.id = id & kCanStdIdMask;
  f.len = 8;
  f.data[0] = node_id;
  f.data[1] = data_type;
  f.data[2] = service_code;
  f.data[3] = message_code;
  bytes::store_u32(f.data.data() + 4, raw, Order::Big);
  return f;
}

CanFrame make_canaerospace_float(std::uint16_t id, std::uint8_t node_id, std::uint8_t message_code, float v) {
  return make_canaerospace_frame(id, node_id, kCanAsFloat, 0, message_code, std::bit_cast<std::uint32_t>(v));
}

// ---------------------------------------------------------------------------

const char* can_field_name(std::uint32_t bit) {
  switch (bit) {
    case can_field::kPitch: return "pitch";
    case can_field::kRoll: return "roll";
    case can_field::kHeading: return "heading";
    case can_field::kAltitude: return "altitude";
    case can_field::kLatitude: return "latitude";
    case can_field::kLongitude: return "longitude";
    case can_field::kRollRate: return "roll_rate";
    case can_field::kPitchRate: return "pitch_rate";
    case can_field::kYawRate: return "yaw_rate";
    default: return "unknown";
  }
}

namespace {
// Field indices (bit positions in can_field).
constexpr int kFPitch = 0, kFRoll = 1, kFHeading = 2, kFAlt = 3, kFLat = 4, kFLon = 5, kFRollRate = 6,
              kFPitchRate = 7, kFYawRate = 8;

bool position_in_range(int field, double v) {
  if (field == kFLat) return v >= -90.0 && v <= 90.0;
  return v >= -180.0 && v < 360.0;
}
}  // namespace

CanPoseAssembler::CanPoseAssembler(CanPoseConfig config) : config_(config) {}

void CanPoseAssembler::reset() {
  fields_ = {};
  high_ = {};
  updated_ = 0;
}

void CanPoseAssembler::set(int field_index, double value, double t_s) {
  Field& f = fields_[static_cast<std::size_t>(field_index)];
  f.value = value;
  f.t_s = t_s;
  f.seen = true;
  updated_ |= 1u << field_index;
  ++stats_.used;
}

std::uint32_t CanPoseAssembler::required_fields() const {
  std::uint32_t required = can_field::kPitch | can_field::kRoll | can_field::kHeading | can_field::kAltitude;
  const bool position_never_seen = !fields_[kFLat].seen && !fields_[kFLon].seen;
  if (config_.require_position || !position_never_seen) required |= can_field::kLatitude | can_field::kLongitude;
  return required;
}

void CanPoseAssembler::feed_half(int which, const CanAerospaceValue& v, double t_s) {
  PendingHigh& h = high_[static_cast<std::size_t>(which)];
  const int field = which == 0 ? kFLat : kFLon;
  if (v.data_type == kCanAsDoubleH) {
    if (h.pending) ++stats_.orphan_high;
    h.raw = v.raw;
    h.code = v.message_code;
    h.pending = true;
    return;
  }
  // DOUBLEL
  if (!h.pending) {
    ++stats_.orphan_low;
    return;
  }
  h.pending = false;
  if (h.code != v.message_code) {
    ++stats_.half_mismatch;
    return;
  }
  const double d = std::bit_cast<double>((static_cast<std::uint64_t>(h.raw) << 32) | v.raw);
  if (!std::isfinite(d)) {
    ++stats_.non_finite;
    return;
  }
  if (!position_in_range(field, d)) {
    ++stats_.out_of_range;
    return;
  }
  set(field, d, t_s);
}

void CanPoseAssembler::feed(const CanAerospaceValue& v, double t_s) {
  ++stats_.fed;
  const bool is_float = v.data_type == kCanAsFloat;
  const bool is_half = v.data_type == kCanAsDoubleH || v.data_type == kCanAsDoubleL;
  if (!is_float && !is_half) {  // not from decode_canaerospace
    ++stats_.unused_id;
    return;
  }
  if (is_float && !std::isfinite(v.value)) {
    ++stats_.non_finite;
    return;
  }
  if (is_position_id(v.id)) {
    const int which = v.id == canas_id::kLatitude ? 0 : 1;
    if (is_half) {
      feed_half(which, v, t_s);
      return;
    }
    const int field = which == 0 ? kFLat : kFLon;
    if (!position_in_range(field, v.value)) {
      ++stats_.out_of_range;
      return;
    }
    set(field, v.value, t_s);
    return;
  }
  if (is_half) {  // DOUBLE halves only for lat / lon
    ++stats_.unused_id;
    return;
  }
  if (canaerospace_is_altitude_id(v.id)) {
    if (v.id != config_.altitude_id) {
      ++stats_.unused_id;
      return;
    }
    set(kFAlt, v.value, t_s);
    return;
  }
  switch (v.id) {
    case canas_id::kBodyPitch: set(kFPitch, v.value, t_s); return;
    case canas_id::kBodyRoll: set(kFRoll, v.value, t_s); return;
    case canas_id::kHeading: set(kFHeading, v.value, t_s); return;
    case canas_id::kBodyRollRate: set(kFRollRate, v.value, t_s); return;
    case canas_id::kBodyPitchRate: set(kFPitchRate, v.value, t_s); return;
    case canas_id::kBodyYawRate: set(kFYawRate, v.value, t_s); return;
    default: ++stats_.unused_id; return;
  }
}

std::optional<PoseMessage> CanPoseAssembler::pose(double now_s, StaleFields& stale) {
  stale = StaleFields{};
  for (int i = 0; i < can_field::kCount; ++i) {
    const Field& f = fields_[static_cast<std::size_t>(i)];
    const std::uint32_t bit = 1u << i;
    if (!f.seen) {
      stale.missing |= bit;
    } else if (now_s - f.t_s > config_.max_age_s) {
      stale.stale |= bit;
    }
  }
  const std::uint32_t bad = stale.stale | stale.missing;
  const std::uint32_t required = required_fields();
  const bool geodetic = (required & can_field::kLatitude) != 0;
  if ((bad & required) != 0) {
    ++stats_.no_pose;
    return std::nullopt;
  }
  PoseMessage m;
  m.frame = geodetic ? PoseMessage::Frame::Geodetic : PoseMessage::Frame::Local;
  m.position = {geodetic ? fields_[kFLat].value : 0.0, geodetic ? fields_[kFLon].value : 0.0,
                fields_[kFAlt].value};
  m.pitch_deg = fields_[kFPitch].value;
  m.roll_deg = fields_[kFRoll].value;
  m.heading_deg = fields_[kFHeading].value;
  const std::uint32_t rate_bits = can_field::kRollRate | can_field::kPitchRate | can_field::kYawRate;
  if ((bad & rate_bits) == 0) {
    m.has_rates = true;
    m.body_rates_dps = {fields_[kFRollRate].value, fields_[kFPitchRate].value, fields_[kFYawRate].value};
  }
  if (auto why = validate_and_normalize(m)) {
    stale.reject = *why;
    ++stats_.no_pose;
    return std::nullopt;
  }
  ++stats_.poses;
  return m;
}

// ---------------------------------------------------------------------------

std::uint8_t CanAerospaceEncoder::next_code(std::uint16_t id) {
  const int i = canaerospace_id_index(id);
  if (i < 0) return 0;
  return codes_[static_cast<std::size_t>(i)]++;
}

void CanAerospaceEncoder::encode(const PoseMessage& pose, std::vector<CanFrame>& out) {
  const std::uint8_t node = config_.node_id;
  auto put_float = [&](std::uint16_t id, double v) {
    out.push_back(make_canaerospace_float(id, node, next_code(id), bytes::narrow_f32(v)));
  };
  put_float(canas_id::kBodyPitch, pose.pitch_deg);
  put_float(canas_id::kBodyRoll, pose.roll_deg);
  put_float(canas_id::kHeading, pose.heading_deg);
  put_float(config_.altitude_id, pose.position.z);
  if (pose.frame == PoseMessage::Frame::Geodetic) {
    for (int k = 0; k < 2; ++k) {
      const std::uint16_t id = k == 0 ? canas_id::kLatitude : canas_id::kLongitude;
      const double v = pose.position[k];
      if (config_.position_as_double) {
        const std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
        const std::uint8_t code = next_code(id);
        out.push_back(make_canaerospace_frame(id, node, kCanAsDoubleH, 0, code, static_cast<std::uint32_t>(bits >> 32)));
        out.push_back(make_canaerospace_frame(id, node, kCanAsDoubleL, 0, code, static_cast<std::uint32_t>(bits)));
      } else {
        put_float(id, v);
      }
    }
  }
  if (config_.send_rates && pose.has_rates) {
    put_float(canas_id::kBodyPitchRate, pose.body_rates_dps.y);
    put_float(canas_id::kBodyRollRate, pose.body_rates_dps.x);
    put_float(canas_id::kBodyYawRate, pose.body_rates_dps.z);
  }
}

std::vector<CanFrame> CanAerospaceEncoder::encode(const PoseMessage& pose) {
  std::vector<CanFrame> out;
  out.reserve(11);
  encode(pose, out);
  return out;
}

}  // namespace ig::io::wire
