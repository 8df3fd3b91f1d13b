// The scenario's path section: the ownship's key poses (docs/scenario.md).
#include <cmath>
#include <string>

#include "io/scenario_json.h"

namespace ig::io::scenario_json {

PathSpec parse_path(const json& j, const std::string& path) {
  require_object(j, path);
  check_keys(j, path, {"frame", "altitude", "keys"});
  PathSpec ps;
  if (j.contains("frame")) {
    ps.frame = get_choice(j["frame"], child(path, "frame"), {"local", "geodetic"}) == "local" ? PositionFrame::Local
                                                                                             : PositionFrame::Geodetic;
  }
  if (j.contains("altitude")) {
    ps.altitude = get_choice(j["altitude"], child(path, "altitude"), {"msl", "agl"}) == "msl"
                      ? AltitudeMode::AboveSeaLevel
                      : AltitudeMode::AboveGround;
  }
  const std::string kp = child(path, "keys");
  if (!j.contains("keys")) fail(kp, "required key is missing (at least one key is needed)");
  const json& keys = j["keys"];
  require_array(keys, kp);
  if (keys.empty()) fail(kp, "must contain at least one key");
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const std::string p = element(kp, i);
    const json& k = keys[i];
    require_object(k, p);
    check_keys(k, p, {"t", "position", "hpr"});
    PathKey key;
    if (!k.contains("t")) fail(child(p, "t"), "required key is missing");
    key.t_s = get_number_in(k["t"], child(p, "t"), 0.0, kMaxTimeS);
    if (!ps.keys.empty() && !(key.t_s > ps.keys.back().t_s)) {
      fail(child(p, "t"), "key times must be strictly increasing (previous key at " + num(ps.keys.back().t_s) +
                              ", this one at " + num(key.t_s) + ")");
    }
    const std::string pp = child(p, "position");
    if (!k.contains("position")) fail(pp, "required key is missing");
    key.position = get_vec3(k["position"], pp);
    if (ps.frame == PositionFrame::Local) {
      for (std::size_t a = 0; a < 3; ++a) {
        if (std::fabs(key.position[a]) > kMaxDistanceM) {
          fail(element(pp, a), "must be in [" + num(-kMaxDistanceM) + ", " + num(kMaxDistanceM) + "]" +
                                   got(k["position"][a]));
        }
      }
    } else {
      const double lat = key.position[0], lon = key.position[1], alt = key.position[2];
      if (!(lat >= -90.0 && lat <= 90.0)) fail(element(pp, 0), "latitude must be in [-90, 90]" + got(k["position"][0]));
      if (!(lon >= -180.0 && lon < 360.0)) fail(element(pp, 1), "longitude must be in [-180, 360)" + got(k["position"][1]));
      if (!(std::fabs(alt) <= kMaxDistanceM)) {
        fail(element(pp, 2), "altitude must be in [" + num(-kMaxDistanceM) + ", " + num(kMaxDistanceM) + "]" +
                                 got(k["position"][2]));
      }
    }
    if (k.contains("hpr")) {
      const std::string hp = child(p, "hpr");
      const std::array<double, 3> hpr = get_vec3(k["hpr"], hp);
      if (std::fabs(hpr[0]) > kMaxAngleDeg) fail(element(hp, 0), "heading must be in [-1e6, 1e6]" + got(k["hpr"][0]));
      if (!(hpr[1] >= -90.0 && hpr[1] <= 90.0)) fail(element(hp, 1), "pitch must be in [-90, 90]" + got(k["hpr"][1]));
      if (std::fabs(hpr[2]) > kMaxAngleDeg) fail(element(hp, 2), "roll must be in [-1e6, 1e6]" + got(k["hpr"][2]));
      key.heading_deg = hpr[0];
      key.pitch_deg = hpr[1];
      key.roll_deg = hpr[2];
    }
    ps.keys.push_back(key);
  }
  return ps;
}

}  // namespace ig::io::scenario_json
