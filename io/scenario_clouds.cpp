// The scenario's environment.clouds: cloud layers (docs/scenario.md).
#include <string>

#include "io/scenario_json.h"

namespace ig::io::scenario_json {

options::CloudLayers parse_clouds(const json& j, const std::string& path) {
  require_array(j, path);
  if (j.size() > std::size_t(options::kMaxCloudLayers))
    fail(path, "at most " + std::to_string(options::kMaxCloudLayers) + " cloud layers (got " +
                   std::to_string(j.size()) + ")");
  options::CloudLayers out;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string p = element(path, i);
    const json& c = j[i];
    require_object(c, p);
    check_keys(c, p, {"type", "coverage_pct", "base_m", "thickness_m", "transition_m", "visibility_m", "scud_pct",
                      "wind_mps", "wind_from_deg"});
    options::CloudLayer l;
    l.id = int(i) + 1;
    if (!c.contains("type")) fail(child(p, "type"), "required key is missing");
    const std::string type = get_string(c["type"], child(p, "type"));
    const auto t = options::cloud_type_named(type);
    if (!t) {
      std::string names;
      for (auto n : options::kCloudTypeNames) names += (names.empty() ? "" : ", ") + std::string(n);
      fail(child(p, "type"), "unknown cloud type (one of " + names + ")" + got(c["type"]));
    }
    l.type = *t;
    if (c.contains("coverage_pct")) l.coverage = get_number_in(c["coverage_pct"], child(p, "coverage_pct"), 0, 100) / 100.0;
    if (!c.contains("base_m")) fail(child(p, "base_m"), "required key is missing");
    l.base_m = get_number_in(c["base_m"], child(p, "base_m"), -1000.0, 100000.0);
    if (c.contains("thickness_m")) l.thickness_m = get_number_in(c["thickness_m"], child(p, "thickness_m"), 0.0, 100000.0);
    if (l.base_m + l.thickness_m > 100000.0) fail(child(p, "thickness_m"), "the top is above 100 km");
    if (c.contains("transition_m"))
      l.transition_m = get_number_in(c["transition_m"], child(p, "transition_m"), 0.0, 10000.0);
    if (c.contains("visibility_m"))
      l.visibility_m = get_number_in(c["visibility_m"], child(p, "visibility_m"), 1.0, 1000000.0);
    if (c.contains("scud_pct")) l.scud = get_number_in(c["scud_pct"], child(p, "scud_pct"), 0, 100) / 100.0;
    double speed = 0.0, from_deg = 0.0;
    if (c.contains("wind_mps")) speed = get_number_in(c["wind_mps"], child(p, "wind_mps"), 0.0, 200.0);
    if (c.contains("wind_from_deg")) from_deg = get_number_in(c["wind_from_deg"], child(p, "wind_from_deg"), -360.0, 360.0);
    l.wind_mps = options::wind_from(speed, from_deg);
    out.push_back(l);
  }
  return out;
}

}  // namespace ig::io::scenario_json
