#pragma once
// CANaerospace (CAN 2.0A) pose parameters: frame decode / encode and the
// assembler that forms a PoseMessage from the freshest value of each field.
// Pure data, no sockets. Id map, units and rules: docs/can.md.
//
// Frame payload (8 bytes): [0] node id, [1] data type, [2] service code,
// [3] message code (increments per id), [4..7] value, big-endian.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "io/wire/can_frame.h"
#include "io/wire/pose_message.h"

namespace ig::io::wire {

// Data type codes used here.
inline constexpr std::uint8_t kCanAsFloat = 2;     // IEEE f32
inline constexpr std::uint8_t kCanAsDoubleH = 30;  // high 32 bits of an f64
inline constexpr std::uint8_t kCanAsDoubleL = 31;  // low 32 bits of an f64

// Parameter ids (11-bit CAN ids) the IG understands.
namespace canas_id {
inline constexpr std::uint16_t kBodyPitchRate = 303;  // deg/s, FLOAT
inline constexpr std::uint16_t kBodyRollRate = 304;   // deg/s, FLOAT
inline constexpr std::uint16_t kBodyYawRate = 305;    // deg/s, FLOAT
inline constexpr std::uint16_t kBodyPitch = 311;      // deg, FLOAT
inline constexpr std::uint16_t kBodyRoll = 312;       // deg, FLOAT
inline constexpr std::uint16_t kBaroAltitude = 320;   // m, FLOAT
inline constexpr std::uint16_t kHeading = 321;        // deg, FLOAT
inline constexpr std::uint16_t kStdAltitude = 322;    // m, FLOAT
inline constexpr std::uint16_t kTrueAltitude = 332;   // m, FLOAT
inline constexpr std::uint16_t kLatitude = 1036;      // deg, FLOAT or DOUBLEH+DOUBLEL
inline constexpr std::uint16_t kLongitude = 1037;     // deg, FLOAT or DOUBLEH+DOUBLEL
}  // namespace canas_id

// Number of known ids (size of the per-id tables).
inline constexpr int kCanAsKnownIdCount = 11;
// Index of `id` in the known-id table, or -1.
int canaerospace_id_index(std::uint32_t id);
// True for an altitude id the assembler can use (320, 322, 332).
bool canaerospace_is_altitude_id(std::uint16_t id);

struct CanAerospaceValue {
  std::uint16_t id = 0;
  std::uint8_t node_id = 0;
  std::uint8_t data_type = 0;
  std::uint8_t service_code = 0;
  std::uint8_t message_code = 0;
  std::uint32_t raw = 0;  // the 4 value bytes as a big-endian u32 (DOUBLEH/L half)
  float value = 0.0f;     // FLOAT: the value (finite); DOUBLEH/L: 0
};

enum class CanAsReject {
  NotClassicFrame,  // FD, extended id, RTR or error frame
  UnknownId,        // id not in the table above (not ours)
  WrongDlc,         // payload length != 8
  WrongNode,        // node id filter set and not matching
  WrongDataType,    // data type not allowed for this id
  NonFinite,        // FLOAT NaN or Inf
};

struct CanAerospaceOptions {
  std::optional<std::uint8_t> node_id;  // accept only this node when set
};

// Counters plus the message-code continuity state. One instance per stream.
struct CanAerospaceStats {
  std::uint64_t frames = 0;  // every frame handed to decode
  std::uint64_t accepted = 0;
  std::uint64_t not_classic = 0;
  std::uint64_t unknown_id = 0;
  std::uint64_t wrong_dlc = 0;
  std::uint64_t wrong_node = 0;
  std::uint64_t wrong_type = 0;
  std::uint64_t non_finite = 0;
  // Accepted frames whose message code is not previous + 1 (mod 256) for the
  // same id (DOUBLEL halves tracked apart from FLOAT / DOUBLEH).
  std::uint64_t code_gaps = 0;
  std::optional<CanAsReject> last_reject;

  std::uint64_t rejected() const {
    return not_classic + unknown_id + wrong_dlc + wrong_node + wrong_type + non_finite;
  }

  // Continuity state: last message code per (known id, half), -1 = none yet.
  std::array<std::int16_t, 2 * kCanAsKnownIdCount> last_code = make_unset();

 private:
  static std::array<std::int16_t, 2 * kCanAsKnownIdCount> make_unset() {
    std::array<std::int16_t, 2 * kCanAsKnownIdCount> a{};
    a.fill(-1);
    return a;
  }
};

// Decodes one frame. Never throws; reads only data[0, len). A rejected frame
// is counted in `stats` (and stats.last_reject set) and yields nullopt.
// Checks in order: classic 11-bit data frame, known id, len == 8, node id,
// data type for the id, FLOAT finite. Continuity is tracked for accepted
// frames only.
std::optional<CanAerospaceValue> decode_canaerospace(const CanFrame& frame, CanAerospaceStats& stats,
                                                     const CanAerospaceOptions& options = {});

// Builds one 8-byte CANaerospace frame.
CanFrame make_canaerospace_frame(std::uint16_t id, std::uint8_t node_id, std::uint8_t data_type,
                                 std::uint8_t service_code, std::uint8_t message_code, std::uint32_t raw);
CanFrame make_canaerospace_float(std::uint16_t id, std::uint8_t node_id, std::uint8_t message_code, float v);

// ---------------------------------------------------------------------------
// Pose assembly.

// Field bits for StaleFields.
namespace can_field {
inline constexpr std::uint32_t kPitch = 1u << 0;
inline constexpr std::uint32_t kRoll = 1u << 1;
inline constexpr std::uint32_t kHeading = 1u << 2;
inline constexpr std::uint32_t kAltitude = 1u << 3;
inline constexpr std::uint32_t kLatitude = 1u << 4;
inline constexpr std::uint32_t kLongitude = 1u << 5;
inline constexpr std::uint32_t kRollRate = 1u << 6;
inline constexpr std::uint32_t kPitchRate = 1u << 7;
inline constexpr std::uint32_t kYawRate = 1u << 8;
inline constexpr int kCount = 9;
}  // namespace can_field
const char* can_field_name(std::uint32_t bit);

// What pose() found: fields received at least once but older than max_age
// (stale), fields never received (missing), and a validation reject of the
// assembled pose if any.
struct StaleFields {
  std::uint32_t stale = 0;
  std::uint32_t missing = 0;
  std::optional<Reject> reject;
  bool any() const { return stale != 0 || missing != 0 || reject.has_value(); }
};

struct CanPoseConfig {
  std::uint16_t altitude_id = canas_id::kStdAltitude;  // 320, 322 or 332
  double max_age_s = 0.1;
  // true: no pose without fresh latitude and longitude. false: while neither
  // has ever been received the pose is Local at (0, 0, altitude); once one
  // has been received both are required like with true.
  bool require_position = true;
};

struct CanPoseAssemblerStats {
  std::uint64_t fed = 0;
  std::uint64_t used = 0;          // values that updated a field
  std::uint64_t unused_id = 0;     // known id not used by this config (other altitude id)
  std::uint64_t orphan_low = 0;    // DOUBLEL with no pending DOUBLEH
  std::uint64_t orphan_high = 0;   // DOUBLEH replaced before its DOUBLEL came
  std::uint64_t half_mismatch = 0; // DOUBLEL message code != pending DOUBLEH's
  std::uint64_t non_finite = 0;    // assembled double NaN / Inf
  std::uint64_t out_of_range = 0;  // lat outside [-90, 90] or lon outside [-180, 360)
  std::uint64_t poses = 0;         // pose() calls that returned a pose
  std::uint64_t no_pose = 0;       // pose() calls that returned nullopt
};

// Keeps the freshest value of each field. Lat / lon pairs: a DOUBLEH is held
// until the DOUBLEL with the same message code arrives (the high half is sent
// first); only then is the f64 used, timed by the DOUBLEL's receive time.
class CanPoseAssembler {
 public:
  explicit CanPoseAssembler(CanPoseConfig config = {});

  // Feeds one decoded value received at `t_s` (any monotonic clock, the same
  // one as pose()'s `now_s`).
  void feed(const CanAerospaceValue& v, double t_s);

  // The pose from the freshest values, or nullopt when a required field
  // (pitch, roll, heading, altitude, and lat / lon per require_position) is
  // missing or stale, or the assembled pose fails validate_and_normalize.
  // Rates are optional: has_rates only when all three are fresh. `stale`
  // is overwritten with what was found (also when a pose is returned, e.g.
  // stale rates).
  std::optional<PoseMessage> pose(double now_s, StaleFields& stale);

  const CanPoseAssemblerStats& stats() const { return stats_; }
  const CanPoseConfig& config() const { return config_; }
  // Fields (can_field bits) updated since clear_updated(): a receiver emits a
  // pose once every required field has a new value, i.e. once per sender cycle.
  std::uint32_t updated_fields() const { return updated_; }
  void clear_updated() { updated_ = 0; }
  // The fields pose() needs now (depends on require_position and history).
  std::uint32_t required_fields() const;
  void reset();  // forget all values (not the stats)

 private:
  struct Field {
    double value = 0.0;
    double t_s = 0.0;
    bool seen = false;
  };
  struct PendingHigh {
    std::uint32_t raw = 0;
    std::uint8_t code = 0;
    bool pending = false;
  };
  void set(int field_index, double value, double t_s);
  void feed_half(int which, const CanAerospaceValue& v, double t_s);  // which 0 lat, 1 lon

  CanPoseConfig config_;
  std::array<Field, can_field::kCount> fields_{};
  std::array<PendingHigh, 2> high_{};
  std::uint32_t updated_ = 0;
  CanPoseAssemblerStats stats_;
};

// ---------------------------------------------------------------------------
// Encoding a pose (sender tool, tests).

struct CanAerospaceEncodeConfig {
  std::uint8_t node_id = 1;
  std::uint16_t altitude_id = canas_id::kStdAltitude;
  bool position_as_double = true;  // DOUBLEH+DOUBLEL pairs, else FLOAT
  bool send_rates = true;          // 303-305 when the pose has rates
};

// Turns poses into frames, keeping a message code counter per id (both halves
// of a DOUBLE pair carry the same code). Order per pose: 311, 312, 321,
// altitude, 1036 (H, L), 1037 (H, L), 303, 304, 305. Lat / lon only for a
// Geodetic pose; altitude is position.z. Values are written as given (a NaN
// goes on the wire); service code 0.
class CanAerospaceEncoder {
 public:
  explicit CanAerospaceEncoder(CanAerospaceEncodeConfig config = {}) : config_(config) {}
  std::vector<CanFrame> encode(const PoseMessage& pose);
  void encode(const PoseMessage& pose, std::vector<CanFrame>& out);  // appends

 private:
  std::uint8_t next_code(std::uint16_t id);
  CanAerospaceEncodeConfig config_;
  std::array<std::uint8_t, kCanAsKnownIdCount> codes_{};
};

}  // namespace ig::io::wire
