#pragma once
// The scenario parser's checks (io/scenario*.cpp), shared by every section so
// each key is checked and its errors worded the same way: "<key path>:
// <reason>", thrown as ScenarioError.

#include <array>
#include <cstddef>
#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "io/scenario.h"

namespace ig::io::scenario_json {

using json = nlohmann::json;

// Limits beyond the documented ranges that keep arithmetic far from overflow.
inline constexpr double kMaxDistanceM = 1e9;      // far plane, fog, local positions
inline constexpr double kMaxAngleDeg = 1e6;       // heading / roll values (wrapped)
inline constexpr double kMaxTimeS = 1e7;          // key times and duration (~115 days)
inline constexpr std::size_t kMaxScenarioEntities = 10000;  // as the live entity table's cap
inline constexpr long long kMaxFrames = 100000000;  // duration / step + 1
inline constexpr int kMaxImageSide = 16384;

[[noreturn]] void fail(const std::string& key_path, const std::string& reason);

std::string child(const std::string& path, std::string_view key);

std::string element(const std::string& path, std::size_t i);

// Shortest text that reads back as the same double.
std::string num(double v);

// The offending value, shortened, for "(got ...)" in messages.
std::string shown(const json& j);
// " (got VALUE)", appended to a reason.
std::string got(const json& j);

void require_object(const json& j, const std::string& path);

void require_array(const json& j, const std::string& path);

// Rejects every key of object `j` that is not listed.
void check_keys(const json& j, const std::string& path, std::initializer_list<std::string_view> allowed);

double get_number(const json& j, const std::string& path);

// Closed range [lo, hi].
double get_number_in(const json& j, const std::string& path, double lo, double hi);

// (0, hi]
double get_positive(const json& j, const std::string& path, double hi);

long long get_integer(const json& j, const std::string& path, long long lo, long long hi);

std::string get_string(const json& j, const std::string& path);

std::string get_nonempty_string(const json& j, const std::string& path);

bool get_bool(const json& j, const std::string& path);

std::string get_choice(const json& j, const std::string& path, std::initializer_list<std::string_view> choices);

std::array<double, 3> get_vec3(const json& j, const std::string& path);

glm::vec3 get_colour(const json& j, const std::string& path);

// Names end up in output file names: keep them to something path-safe.
std::string get_name(const json& j, const std::string& path);

// terrain.generator and terrain.void_fill (scenario_terrain.cpp).
options::SyntheticTerrainOptions parse_generator(const json& j, const std::string& path);
options::VoidFillOptions parse_void_fill(const json& j, const std::string& path);
// terrain.water: "auto", "off", a path, or {"file": path, "level_attribute": name};
// file_path resolves a path value as the scenario's other file keys are.
options::WaterOptions parse_water(const json& j, const std::string& path,
                                  const std::function<std::string(const json&, const std::string&)>& file_path);

// path (scenario_path.cpp).
PathSpec parse_path(const json& j, const std::string& path = "path");
// "entities": scripted entities, each on a path like the ownship's (scenario_entities.cpp).
std::vector<EntitySpec> parse_entities(const json& j);

// environment.clouds: the cloud layers (scenario_clouds.cpp).
options::CloudLayers parse_clouds(const json& j, const std::string& path);

// render.twolevel and the baselines' sections of `render` into r
// (scenario_methods.cpp).
void parse_method_options(const json& render, const std::string& path, RenderSpec& r);

}  // namespace ig::io::scenario_json
