// The scenario's terrain.generator, terrain.void_fill and terrain.water sections
// (docs/scenario.md).
#include "io/scenario_json.h"

namespace ig::io::scenario_json {

options::SyntheticTerrainOptions parse_generator(const json& j, const std::string& path) {
  require_object(j, path);
  check_keys(j, path, {"size", "seed", "spacing_m", "relief_m", "base_m", "octaves", "ridge_weight", "origin"});
  options::SyntheticTerrainOptions g;
  if (j.contains("size")) {
    const std::string p = child(path, "size");
    const std::string rule = "must be 2^n+1 in [3, 16385] (e.g. 257, 1025, 4097)";
    long long n = 0;
    try {
      n = get_integer(j["size"], p, 3, 16385);
    } catch (const ScenarioError&) {
      fail(p, rule + (j["size"].is_number() ? got(j["size"]) : std::string(" (got ") + j["size"].type_name() + ")"));
    }
    const long long m = n - 1;
    if ((m & (m - 1)) != 0) fail(p, rule + got(j["size"]));
    g.size = static_cast<int>(n);
  }
  if (j.contains("seed")) g.seed = static_cast<unsigned>(get_integer(j["seed"], child(path, "seed"), 0, 4294967295LL));
  if (j.contains("spacing_m")) g.spacing_m = get_positive(j["spacing_m"], child(path, "spacing_m"), 1e5);
  if (j.contains("relief_m")) g.relief_m = get_number_in(j["relief_m"], child(path, "relief_m"), 0.0, 1e5);
  if (j.contains("base_m")) g.base_m = get_number_in(j["base_m"], child(path, "base_m"), -1e5, 1e5);
  if (j.contains("octaves")) g.octaves = static_cast<int>(get_integer(j["octaves"], child(path, "octaves"), 1, 20));
  if (j.contains("ridge_weight")) g.ridge_weight = get_number_in(j["ridge_weight"], child(path, "ridge_weight"), 0.0, 1.0);
  if (j.contains("origin")) {
    const std::string p = child(path, "origin");
    if (!j["origin"].is_array() || j["origin"].size() != 2) fail(p, "must be [lat_deg, lon_deg]" + got(j["origin"]));
    const double lat = get_number_in(j["origin"][0], element(p, 0), -85.0, 85.0);
    const double lon = get_number_in(j["origin"][1], element(p, 1), -180.0, 180.0);
    g.origin_lat_lon = std::array<double, 2>{lat, lon};
  }
  return g;
}

options::VoidFillOptions parse_void_fill(const json& j, const std::string& path) {
  require_object(j, path);
  check_keys(j, path, {"max_distance", "smoothing_iterations"});
  options::VoidFillOptions f;
  if (j.contains("max_distance"))
    f.max_distance = static_cast<int>(
        get_integer(j["max_distance"], child(path, "max_distance"), 1, options::VoidFillOptions::kMaxVoidSearch));
  if (j.contains("smoothing_iterations"))
    f.smoothing_iterations = static_cast<int>(get_integer(j["smoothing_iterations"], child(path, "smoothing_iterations"),
                                                          0, options::VoidFillOptions::kMaxVoidSmoothing));
  return f;
}

options::WaterOptions parse_water(const json& j, const std::string& path,
                                  const std::function<std::string(const json&, const std::string&)>& file_path) {
  options::WaterOptions w;
  if (j.is_string()) {
    const std::string v = j.get<std::string>();
    if (v == "auto" || v == "off") {
      w.source = v == "auto" ? options::WaterSource::Auto : options::WaterSource::Off;
      return w;
    }
    w.source = options::WaterSource::File;
    w.file = file_path(j, path);
    return w;
  }
  if (!j.is_object())
    fail(path, "must be \"auto\", \"off\", a water file's path or {\"file\": ..., \"level_attribute\": ...}" + got(j));
  check_keys(j, path, {"file", "level_attribute"});
  if (!j.contains("file")) fail(child(path, "file"), "is required in the object form");
  w.source = options::WaterSource::File;
  w.file = file_path(j["file"], child(path, "file"));
  if (j.contains("level_attribute")) w.level_attribute = get_nonempty_string(j["level_attribute"], child(path, "level_attribute"));
  return w;
}

}  // namespace ig::io::scenario_json
