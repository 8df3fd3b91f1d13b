#include "session/host_environment.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <variant>

#include "environment/cloud_layers.h"

namespace ig::session {

using namespace io::wire;

namespace {

const char* object_class_name(int c) {
  static constexpr const char* kNames[] = {"entity", "articulated part", "view", "view group", "motion tracker"};
  return c >= 0 && c < 5 ? kNames[c] : "object";
}

// Humidity, temperature, winds and pressure as the host set them (Atmosphere
// Control), else the ICAO standard atmosphere at `altitude_m` (15 °C and
// 1013.25 hPa at sea level, -6.5 K/km in the troposphere, dry and calm):
// never the 0 hPa of an unset field.
CigiWeatherConditions weather_conditions(const std::optional<CigiAtmosphere>& set, double altitude_m) {
  CigiWeatherConditions w;
  if (set) {
    w.humidity_pct = set->humidity_pct;
    w.air_temp_c = set->air_temp_c;
    w.horizontal_wind_mps = set->horizontal_wind_mps;
    w.vertical_wind_mps = set->vertical_wind_mps;
    w.wind_direction_deg = set->wind_direction_deg;
    w.pressure_hpa = set->pressure_hpa;
    return w;
  }
  const double h = std::clamp(altitude_m, -1000.0, 11000.0);  // the troposphere's formula
  w.air_temp_c = float(15.0 - 0.0065 * h);
  w.pressure_hpa = float(1013.25 * std::pow(1.0 - 0.0065 * h / 288.15, 5.25588));
  return w;
}

// IG Message ids: 1000 and up, one per message sent.
constexpr std::uint16_t kMessageIdBase = 1000;

}  // namespace

HostEnvironment::HostEnvironment(HostServices& services, LocalToGeodetic to_geodetic, double visibility_m)
    : services_(services),
      to_geodetic_(std::move(to_geodetic)),
      own_visibility_m_(visibility_m),
      visibility_in_force_m_(visibility_m) {
  for (const char* name : {"celestial_sphere_controls", "atmosphere_controls", "weather_controls", "rate_controls",
                           "position_requests", "position_responses", "collision_segments", "collision_notifications",
                           "conditions_requests", "weather_responses", "ig_messages", "resets"})
    counters_.packets[name] = 0;
}

void HostEnvironment::message(const std::string& text) {
  if (announced_.insert(text).second) messages_.push_back(text);
}

void HostEnvironment::take(std::span<const std::uint8_t> datagram) { take(decode_cigi_host_packets(datagram)); }

void HostEnvironment::take(const CigiHostPackets& p) {
  if (!p.ig_mode) return;  // not a host datagram: the pose intake counts it
  const std::uint32_t mode = *p.ig_mode == kCigiModeStandby ? kCigiModeStandby : kCigiModeOperate;
  if (mode == kCigiModeStandby && ig_mode_ != kCigiModeStandby) {
    ++counters_.packets["resets"];
    continuous_.clear();
    segments_.clear();
  }
  ig_mode_ = mode;
  for (const QueryReject r : p.rejects) ++counters_.rejected[query_reject_name(r)];
  for (const std::uint8_t op : p.unsupported) {
    ++counters_.unsupported[op];
    message("opcode " + std::to_string(op) + " is not supported by this IG: counted and ignored");
  }
  if (p.database)
    message("database " + std::to_string(*p.database) +
            " cannot be loaded: this IG renders the terrain it was started with");
  if (!p.celestial.empty()) celestial_ = p.celestial.back();
  counters_.packets["celestial_sphere_controls"] += p.celestial.size();
  if (!p.atmosphere.empty()) {
    atmosphere_ = p.atmosphere.back();
    atmosphere_visibility_m_ = atmosphere_->visibility_m;
  }
  for (const auto& w : p.weather) take_weather(w);
  counters_.packets["atmosphere_controls"] += p.atmosphere.size();
  counters_.packets["weather_controls"] += p.weather.size();
  counters_.packets["rate_controls"] += p.rates.size();  // applied by the pose intake (io/pose_intake.h)
  for (const auto& r : p.positions) {
    ++counters_.packets["position_requests"];
    const auto key = std::make_pair(int(r.of.object_class), int(r.of.object));
    if (r.continuous) {
      continuous_[key] = r;
    } else {
      continuous_.erase(key);  // a one-shot request ends a continuous one
      one_shot_.push_back(r);
    }
  }
  for (const auto& s : p.segments) {
    ++counters_.packets["collision_segments"];
    const auto key = std::make_pair(int(s.entity), int(s.segment));
    if (s.enabled) segments_[key] = s;
    else segments_.erase(key);
  }
  counters_.packets["conditions_requests"] += p.conditions.size();
  conditions_.insert(conditions_.end(), p.conditions.begin(), p.conditions.end());
}

void HostEnvironment::take_weather(const CigiWeatherControl& w) {
  if (w.scope != 0) return;  // regional and entity weather: counted only
  const bool had_cloud = clouds_.erase(w.layer) > 0;
  clouds_changed_ = clouds_changed_ || had_cloud;
  layers_.erase(w.layer);
  if (!w.enabled) return;
  const auto layer = cigi_cloud_layer(w);
  if (!layer) {
    if (w.cloud_type != 0) refuse("weather-cloud-type", "Weather Control layer " + std::to_string(w.layer) +
                                                            ": cloud type " + std::to_string(w.cloud_type) +
                                                            " (other) is not drawn");
    layers_[w.layer] = w;  // weather without cloud: its visibility only
    return;
  }
  // Terrain-independent checks here, per packet; the scene checks the rest.
  const auto check = environment::check_cloud_layer(*layer, -std::numeric_limits<double>::infinity());
  if (!check.layer) {
    refuse("weather-cloud-layer", "Weather Control layer " + std::to_string(w.layer) + ": " + check.refused);
    return;
  }
  clouds_[w.layer] = *check.layer;
  clouds_changed_ = true;
}

void HostEnvironment::refuse(const std::string& reason, const std::string& text) {
  ++counters_.rejected[reason];
  message(text);
}

HostEnvironment::Changes HostEnvironment::changes(double eye_altitude_m,
                                                  const std::function<options::UtcDateTime()>& today) {
  Changes c;
  if (celestial_) {
    options::UtcDateTime t;
    if (!celestial_->date_valid) {
      t = today();
    } else {
      t.year = celestial_->year;
      t.month = celestial_->month;
      t.day = celestial_->day;
    }
    t.hour = celestial_->hour;
    t.minute = celestial_->minute;
    t.second = 0.0;
    c.time_utc = t;
    c.clock_runs = celestial_->ephemeris;
    celestial_.reset();
  }
  std::optional<double> layer;  // the lowest visibility of the layers holding the eye
  for (const auto& [id, w] : layers_)
    if (eye_altitude_m >= w.base_m && eye_altitude_m <= double(w.base_m) + w.thickness_m)
      layer = std::min(layer.value_or(w.visibility_m), double(w.visibility_m));
  const double v = layer.value_or(atmosphere_visibility_m_.value_or(own_visibility_m_));
  if (v != visibility_in_force_m_) c.visibility_m = visibility_in_force_m_ = v;
  if (clouds_changed_) {
    options::CloudLayers layers;
    for (const auto& [id, l] : clouds_) layers.push_back(l);
    c.clouds = std::move(layers);
    clouds_changed_ = false;
  }
  return c;
}

std::optional<CigiPositionResponse> HostEnvironment::position_of(const CigiPositionRequest& r,
                                                                 const io::Pose& ownship,
                                                                 std::span<const io::Pose> views) const {
  const io::Pose* pose = nullptr;
  const CigiObjectRef& of = r.of;
  std::optional<io::Pose> entity;
  if (of.object_class == kCigiObjectEntity && of.object == kCigiOwnshipEntity) pose = &ownship;
  else if (of.object_class == kCigiObjectEntity && entity_lookup_) entity = entity_lookup_(of.object, std::nullopt);
  else if (of.object_class == kCigiObjectPart && entity_lookup_) entity = entity_lookup_(of.object, of.part);
  if (entity) pose = &*entity;
  if (of.object_class == kCigiObjectView && of.object < views.size()) pose = &views[of.object];
  if (!pose || !to_geodetic_) return std::nullopt;
  const auto g = to_geodetic_(pose->position);
  if (!g) return std::nullopt;
  const io::Hpr hpr = io::hpr_from_attitude(pose->attitude);
  CigiPositionResponse out;
  out.of = of;
  out.of.coords = 0;  // geodetic: the ownship and the views have no parent
  out.position = *g;
  out.roll_deg = float(hpr.roll_deg);
  out.pitch_deg = float(hpr.pitch_deg);
  out.yaw_deg = float(hpr.heading_deg);
  return out;
}

void HostEnvironment::append_frame_packets(const io::Pose& ownship, std::span<const io::Pose> views,
                                           double visibility_m, std::vector<std::uint8_t>& out,
                                           std::size_t max_bytes) {
  const bool swap = false;  // this machine's order, as the Start Of Frame's
  auto fits = [&](std::size_t size) { return out.size() + size <= max_bytes; };
  auto answer_position = [&](const CigiPositionRequest& r) {
    const auto p = position_of(r, ownship, views);
    if (!p) {
      ++counters_.rejected["position-of-unknown-object"];
      message(std::string("Position Request: no such ") + object_class_name(r.of.object_class) + " " +
              std::to_string(r.of.object) + " (entities: active ones; views: the channels)");
      return;
    }
    if (!fits(kCigiPositionResponseSize)) return;
    append_cigi_position_response(*p, swap, out);
    ++counters_.packets["position_responses"];
  };
  for (const auto& r : one_shot_) answer_position(r);
  one_shot_.clear();
  for (const auto& [key, r] : continuous_) answer_position(r);

  for (const auto& [key, s] : segments_) {
    // Cast from the segment's entity (the ownship, or an entity the IG has now).
    std::optional<io::Pose> from;
    if (s.entity == kCigiOwnshipEntity) from = ownship;
    else if (entity_lookup_) from = entity_lookup_(s.entity, std::nullopt);
    if (!from) {
      ++counters_.rejected["segment-of-unknown-entity"];
      continue;
    }
    LosSegmentRequest q;
    q.extended = true;
    q.source_coords = q.destination_coords = CigiCoords::Entity;
    q.entity = kCigiOwnshipEntity;
    q.source = s.start;
    q.destination = s.end;
    const auto answer = services_.cast_collision_segment(q, *from);
    const auto* los = std::get_if<LosResponse>(&answer);
    if (!los || !los->valid || !los->range_valid || !fits(kCigiCollisionSegmentNotificationSize)) continue;
    CigiCollisionNotification n;
    n.entity = s.entity;
    n.segment = s.segment;
    n.material = los->material;
    n.distance_m = float(los->range_m);
    append_cigi_collision_notification(n, swap, out);
    ++counters_.packets["collision_notifications"];
  }

  for (const auto& r : conditions_) {
    if (r.types & kCigiConditionsWeather && fits(kCigiWeatherConditionsResponseSize)) {
      CigiWeatherConditions w = weather_conditions(atmosphere_, r.point.z);
      w.request_id = r.id;
      w.visibility_m = float(visibility_m);
      append_cigi_weather_conditions(w, swap, out);
      ++counters_.packets["weather_responses"];
    }
    if (r.types & ~kCigiConditionsWeather)
      message("Environmental Conditions Request: only weather conditions are modelled here");
  }
  conditions_.clear();

  std::size_t sent = 0;
  for (; sent < messages_.size() && fits(kCigiIgMessageMaxSize); ++sent) {
    append_cigi_ig_message({std::uint16_t(kMessageIdBase + counters_.packets["ig_messages"]), messages_[sent]}, swap, out);
    ++counters_.packets["ig_messages"];
  }
  messages_.erase(messages_.begin(), messages_.begin() + std::ptrdiff_t(sent));
}

nlohmann::json HostEnvironment::summary() const {
  nlohmann::json out(counters_.packets);
  nlohmann::json unsupported = nlohmann::json::object();
  for (const auto& [op, n] : counters_.unsupported) unsupported[std::to_string(op)] = n;
  out["unsupported"] = unsupported;
  out["rejected"] = counters_.rejected;
  out["ig_mode"] = ig_mode_ == kCigiModeStandby ? "standby" : "operate";
  return out;
}

}  // namespace ig::session
