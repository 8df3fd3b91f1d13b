#pragma once
// CIGI 3.3 packets a host sends about the world and its entities beyond
// poses and queries, and the IG's answers to them. Pure bytes, no sockets;
// host packets in the sender's byte order (the IG Control's magic), IG
// packets after a Start Of Frame in its order. Layouts: docs/protocol.md,
// "CIGI 3.3: every packet".

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "io/wire/cigi_queries.h"
#include "options/cloud_options.h"

namespace ig::io::wire {

inline constexpr std::uint8_t kCigiOpRateControl = 8;
inline constexpr std::uint8_t kCigiOpCelestialSphereControl = 9;
inline constexpr std::uint8_t kCigiOpAtmosphereControl = 10;
inline constexpr std::uint8_t kCigiOpWeatherControl = 12;
inline constexpr std::uint8_t kCigiOpCollisionSegmentDefinition = 22;
inline constexpr std::uint8_t kCigiOpPositionRequest = 27;
inline constexpr std::uint8_t kCigiOpEnvironmentalConditionsRequest = 28;
inline constexpr std::uint8_t kCigiOpPositionResponse = 108;
inline constexpr std::uint8_t kCigiOpWeatherConditionsResponse = 109;
inline constexpr std::uint8_t kCigiOpCollisionSegmentNotification = 113;
inline constexpr std::uint8_t kCigiOpIgMessage = 117;
inline constexpr std::size_t kCigiRateControlSize = 32;
inline constexpr std::size_t kCigiCelestialSphereControlSize = 16;
inline constexpr std::size_t kCigiAtmosphereControlSize = 32;
inline constexpr std::size_t kCigiWeatherControlSize = 56;
inline constexpr std::size_t kCigiCollisionSegmentDefinitionSize = 40;
inline constexpr std::size_t kCigiPositionRequestSize = 8;
inline constexpr std::size_t kCigiEnvironmentalConditionsRequestSize = 32;
inline constexpr std::size_t kCigiPositionResponseSize = 48;
inline constexpr std::size_t kCigiWeatherConditionsResponseSize = 32;
inline constexpr std::size_t kCigiCollisionSegmentNotificationSize = 16;
inline constexpr std::size_t kCigiIgMessageMaxSize = 104;

// Rate Control: [2] entity, [4] articulated part, [5] bit 0 apply to the
// part, bit 1 coordinate system (0 world: x north, y east, z down; 1 the
// entity's body axes: x forward, y right, z down); [8] x, [12] y, [16] z
// rates (m/s), [20] roll, [24] pitch, [28] yaw rates (deg/s) - f32.
struct CigiRateControl {
  std::uint16_t entity = 0;
  std::uint8_t part = 0;
  bool apply_to_part = false;
  bool body_axes = false;
  glm::dvec3 velocity_mps{0.0};  // x, y, z as above
  glm::dvec3 rates_dps{0.0};     // roll, pitch, yaw
  bool operator==(const CigiRateControl&) const = default;
};

// Celestial Sphere Control: [2] hour (0-23), [3] minute (0-59), [4] bits
// 0 ephemeris, 1 sun, 2 moon, 3 star field enabled, 4 date valid;
// [8] date as the decimal MMDDYYYY (u32), [12] star field intensity (%).
// The ICD gives the time of day in UTC.
struct CigiCelestialSphere {
  std::uint8_t hour = 0, minute = 0;
  bool ephemeris = false, sun = false, moon = false, stars = false, date_valid = false;
  int month = 1, day = 1, year = 2000;
  float star_intensity = 0;
  bool operator==(const CigiCelestialSphere&) const = default;
};

// Atmosphere Control: [2] bit 0 atmospheric model enabled, [3] humidity (%),
// [4] air temperature (deg C), [8] visibility (m), [12] horizontal and
// [16] vertical wind (m/s), [20] wind direction (deg), [24] barometric
// pressure (hPa) - f32.
struct CigiAtmosphere {
  bool model_enabled = false;
  std::uint8_t humidity_pct = 0;
  float air_temp_c = 0, visibility_m = 0, horizontal_wind_mps = 0, vertical_wind_mps = 0, wind_direction_deg = 0,
        pressure_hpa = 0;
  bool operator==(const CigiAtmosphere&) const = default;
};

// Weather Control: [2] region or entity id, [4] layer, [5] humidity,
// [6] bit 0 weather enabled, 1 scud, 2 random winds, 3 random lightning,
// 4-7 cloud type; [7] bits 0-1 scope (0 global, 1 regional, 2 entity),
// 2-4 severity; then f32: [8] air temperature, [12] visibility range,
// [16] scud frequency, [20] coverage, [24] base elevation, [28] thickness,
// [32] transition band, [36] horizontal and [40] vertical wind, [44] wind
// direction, [48] pressure, [52] aerosol concentration.
struct CigiWeatherControl {
  std::uint16_t id = 0;
  std::uint8_t layer = 0, humidity_pct = 0, cloud_type = 0, scope = 0, severity = 0;
  bool enabled = false;
  bool scud = false;
  float air_temp_c = 0, visibility_m = 0, scud_frequency_pct = 0, coverage_pct = 0, base_m = 0, thickness_m = 0,
        transition_band_m = 0, horizontal_wind_mps = 0, vertical_wind_mps = 0, wind_direction_deg = 0;
  bool operator==(const CigiWeatherControl&) const = default;
};

// Collision Detection Segment Definition: [2] entity, [4] segment id,
// [5] bit 0 enabled, [8] x1, [12] y1, [16] z1, [20] x2, [24] y2, [28] z2
// (m, the entity's body axes: x forward, y right, z down) - f32;
// [32] material mask.
struct CigiCollisionSegment {
  std::uint16_t entity = 0;
  std::uint8_t segment = 0;
  bool enabled = false;
  glm::dvec3 start{0.0}, end{0.0};
  std::uint32_t material_mask = 0;
  bool operator==(const CigiCollisionSegment&) const = default;
};

// Position Request: [2] object id, [4] articulated part, [5] bit 0 update
// mode (0 one-shot, 1 continuous: every frame until a one-shot replaces it),
// bits 1-3 object class (0 entity, 1 articulated part, 2 view, 3 view group,
// 4 motion tracker), bits 4-5 coordinate system (0 geodetic, 1 parent
// entity, 2 submodel).
// The object a Position Request names and its Position Response is about.
struct CigiObjectRef {
  std::uint16_t object = 0;
  std::uint8_t part = 0;
  std::uint8_t object_class = 0;
  std::uint8_t coords = 0;
  bool operator==(const CigiObjectRef&) const = default;
};
struct CigiPositionRequest {
  CigiObjectRef of;
  bool continuous = false;
  bool operator==(const CigiPositionRequest&) const = default;
};
inline constexpr std::uint8_t kCigiObjectEntity = 0;
inline constexpr std::uint8_t kCigiObjectPart = 1;
inline constexpr std::uint8_t kCigiObjectView = 2;

// Environmental Conditions Request: [2] bits 0-3 request type (1 maritime,
// 2 terrestrial, 4 weather, 8 aerosol), [3] request id, [8] latitude,
// [16] longitude (deg), [24] altitude (m) - f64.
struct CigiEnvironmentRequest {
  std::uint8_t types = 0;
  std::uint8_t id = 0;
  glm::dvec3 point{0.0};
  bool operator==(const CigiEnvironmentRequest&) const = default;
};
inline constexpr std::uint8_t kCigiConditionsWeather = 4;

// Everything of a host datagram this file decodes, in datagram order per
// kind, and the opcodes no decoder of this IG takes (counted by opcode).
struct CigiHostPackets {
  std::vector<CigiRateControl> rates;
  std::vector<CigiCelestialSphere> celestial;
  std::vector<CigiAtmosphere> atmosphere;
  std::vector<CigiWeatherControl> weather;
  std::vector<CigiCollisionSegment> segments;
  std::vector<CigiPositionRequest> positions;
  std::vector<CigiEnvironmentRequest> conditions;
  std::vector<QueryReject> rejects;
  std::vector<std::uint8_t> unsupported;  // one entry per packet of an opcode this IG does not act on
  std::optional<std::int8_t> database;    // the IG Control's database number, when not 0 (a load request)
  std::optional<std::uint8_t> ig_mode;    // the IG Control's: 0 reset / standby, 1 operate, 2 debug (nullopt: no usable IG Control)
};

// The same framing checks as decode_cigi_requests: nothing from a datagram
// the pose decoder rejects. Angles and rates must be finite; visibility not
// negative; hour, minute and date within the calendar; geodetic points as
// for HAT/HOT requests.
CigiHostPackets decode_cigi_host_packets(std::span<const std::uint8_t> datagram);
// The opcodes some decoder of this IG acts on (IG Control, Entity Control,
// views, queries and the packets above).
bool cigi_opcode_supported(std::uint8_t op);

// Host-side encoders (hosts and tests), in this machine's order or swapped.
std::array<std::uint8_t, kCigiRateControlSize> encode_cigi_rate_control(const CigiRateControl& r, bool swap);
std::array<std::uint8_t, kCigiCelestialSphereControlSize> encode_cigi_celestial(const CigiCelestialSphere& c,
                                                                                bool swap);
std::array<std::uint8_t, kCigiAtmosphereControlSize> encode_cigi_atmosphere(const CigiAtmosphere& a, bool swap);
std::array<std::uint8_t, kCigiWeatherControlSize> encode_cigi_weather(const CigiWeatherControl& w, bool swap);
// The cloud layer a Weather Control packet describes: its layer id, cloud
// type (1-10; nullopt for 0, none, and 11-15, other), coverage (percent ->
// share), base, thickness, transition band, visibility, scud (when its bit
// is set) and the wind it drifts with (horizontal speed blowing from the
// direction, clockwise from north). Ranges are checked where it is drawn
// (environment::check_cloud_layer).
std::optional<options::CloudLayer> cigi_cloud_layer(const CigiWeatherControl& w);
std::array<std::uint8_t, kCigiCollisionSegmentDefinitionSize> encode_cigi_collision_segment(
    const CigiCollisionSegment& s, bool swap);
std::array<std::uint8_t, kCigiPositionRequestSize> encode_cigi_position_request(const CigiPositionRequest& r,
                                                                                bool swap);
std::array<std::uint8_t, kCigiEnvironmentalConditionsRequestSize> encode_cigi_environment_request(
    const CigiEnvironmentRequest& r, bool swap);

// ------------------------------------------------------------ IG -> host

// Position Response: [2] object id, [4] articulated part, [5] bits 0-2
// object class, bits 3-4 coordinate system; [8] latitude / x, [16]
// longitude / y, [24] altitude / z (f64); [32] roll, [36] pitch, [40] yaw
// (deg, f32).
struct CigiPositionResponse {
  CigiObjectRef of;
  glm::dvec3 position{0.0};
  float roll_deg = 0, pitch_deg = 0, yaw_deg = 0;
  bool operator==(const CigiPositionResponse&) const = default;
};

// Collision Detection Segment Notification: [2] entity, [4] segment id,
// [5] bit 0 collision type (0 terrain / non-entity, 1 entity), [6] contacted
// entity, [8] material code, [12] distance from the segment's first point
// to the intersection (m, f32).
struct CigiCollisionNotification {
  std::uint16_t entity = 0;
  std::uint8_t segment = 0;
  bool with_entity = false;
  std::uint16_t contacted_entity = 0;
  std::uint32_t material = 0;
  float distance_m = 0;
  bool operator==(const CigiCollisionNotification&) const = default;
};

// Weather Conditions Response: [2] request id, [3] humidity, [4] air
// temperature, [8] visibility, [12] horizontal and [16] vertical wind,
// [20] wind direction, [24] pressure - f32.
struct CigiWeatherConditions {
  std::uint8_t request_id = 0, humidity_pct = 0;
  float air_temp_c = 0, visibility_m = 0, horizontal_wind_mps = 0, vertical_wind_mps = 0, wind_direction_deg = 0,
        pressure_hpa = 0;
  bool operator==(const CigiWeatherConditions&) const = default;
};

// IG Message: [2] message id, [4] text, NUL-terminated, the packet padded
// to a multiple of 8 bytes, at most 104 (longer text is cut).
struct CigiIgMessage {
  std::uint16_t id = 0;
  std::string text;
  bool operator==(const CigiIgMessage&) const = default;
};

void append_cigi_position_response(const CigiPositionResponse& r, bool swap, std::vector<std::uint8_t>& out);
void append_cigi_collision_notification(const CigiCollisionNotification& n, bool swap,
                                        std::vector<std::uint8_t>& out);
void append_cigi_weather_conditions(const CigiWeatherConditions& w, bool swap, std::vector<std::uint8_t>& out);
void append_cigi_ig_message(const CigiIgMessage& m, bool swap, std::vector<std::uint8_t>& out);

// The packets above in an IG -> host datagram that starts with a Start Of
// Frame (its magic gives the order); other packets are skipped. nullopt when
// it does not start with a valid Start Of Frame or a packet runs past the end.
struct CigiIgPackets {
  std::vector<CigiPositionResponse> positions;
  std::vector<CigiCollisionNotification> collisions;
  std::vector<CigiWeatherConditions> weather;
  std::vector<CigiIgMessage> messages;
};
std::optional<CigiIgPackets> decode_cigi_ig_packets(std::span<const std::uint8_t> datagram);

}  // namespace ig::io::wire
