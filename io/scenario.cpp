// The scenario file parser (schema: docs/scenario.md): one function per
// section in the schema's order. Over 500 lines because the schema is; kept
// in one file so every key shares the same checks and error wording.
#include "io/scenario.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <set>
#include <sstream>
#include <string_view>

#include <nlohmann/json.hpp>

#include "io/utc_time.h"

namespace ig::io {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

// ---------------------------------------------------------------------------
// Limits beyond the documented ranges that keep arithmetic far from overflow.
constexpr double kMaxDistanceM = 1e9;      // far plane, fog, local positions
constexpr double kMaxAngleDeg = 1e6;       // heading / roll values (wrapped)
constexpr double kMaxTimeS = 1e7;          // key times and duration (~115 days)
constexpr long long kMaxFrames = 100000000;  // duration / step + 1
constexpr int kMaxImageSide = 16384;

// ---------------------------------------------------------------------------
// Error helpers. Internal errors carry "<key path>: <reason>"; the public
// entry points prefix the origin (file name or "<string>").

[[noreturn]] void fail(const std::string& key_path, const std::string& reason) {
  throw ScenarioError(key_path + ": " + reason);
}

std::string child(const std::string& path, std::string_view key) {
  if (path.empty()) return std::string(key);
  return path + "." + std::string(key);
}

std::string element(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

// Shortest text that reads back as the same double.
std::string num(double v) {
  if (v == std::floor(v) && std::fabs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// The offending value, shortened, for "(got ...)" in messages.
std::string shown(const json& j) {
  std::string s = j.is_number() ? num(j.get<double>()) : j.dump();
  if (s.size() > 48) s = s.substr(0, 45) + "...";
  return s;
}

std::string got(const json& j) { return " (got " + shown(j) + ")"; }

// ---------------------------------------------------------------------------
// Typed getters. Every one names the key path on failure.

void require_object(const json& j, const std::string& path) {
  if (!j.is_object()) fail(path, std::string("must be an object (got ") + j.type_name() + ")");
}

void require_array(const json& j, const std::string& path) {
  if (!j.is_array()) fail(path, std::string("must be an array (got ") + j.type_name() + ")");
}

// Rejects every key of object `j` that is not listed.
void check_keys(const json& j, const std::string& path, std::initializer_list<std::string_view> allowed) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string& key = it.key();
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string list;
    for (std::string_view a : allowed) {
      if (!list.empty()) list += ", ";
      list += a;
    }
    fail(child(path, key), "unknown key (expected one of: " + list + ")");
  }
}

double get_number(const json& j, const std::string& path) {
  if (!j.is_number()) fail(path, std::string("must be a number (got ") + j.type_name() + ")");
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(path, "must be a finite number");
  return v;
}

// Closed range [lo, hi].
double get_number_in(const json& j, const std::string& path, double lo, double hi) {
  const double v = get_number(j, path);
  if (!(v >= lo && v <= hi)) fail(path, "must be in [" + num(lo) + ", " + num(hi) + "]" + got(j));
  return v;
}

// (0, hi]
double get_positive(const json& j, const std::string& path, double hi) {
  const double v = get_number(j, path);
  if (!(v > 0.0 && v <= hi)) fail(path, "must be > 0 and <= " + num(hi) + got(j));
  return v;
}

long long get_integer(const json& j, const std::string& path, long long lo, long long hi) {
  const std::string range = "must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi);
  if (!j.is_number()) fail(path, range + " (got " + j.type_name() + ")");
  if (j.is_number_unsigned()) {
    const auto u = j.get<unsigned long long>();
    if (hi < 0 || u > static_cast<unsigned long long>(hi) || static_cast<long long>(u) < lo) fail(path, range + got(j));
    return static_cast<long long>(u);
  }
  if (j.is_number_integer()) {
    const auto v = j.get<long long>();
    if (v < lo || v > hi) fail(path, range + got(j));
    return v;
  }
  // A float that happens to be integral (e.g. 640.0) is accepted.
  const double d = j.get<double>();
  if (!std::isfinite(d) || d != std::floor(d) || d < static_cast<double>(lo) ||
      d > static_cast<double>(hi)) {
    fail(path, range + got(j));
  }
  return static_cast<long long>(d);
}

std::string get_string(const json& j, const std::string& path) {
  if (!j.is_string()) fail(path, std::string("must be a string (got ") + j.type_name() + ")");
  return j.get<std::string>();
}

std::string get_nonempty_string(const json& j, const std::string& path) {
  std::string s = get_string(j, path);
  if (s.empty()) fail(path, "must be a non-empty string");
  return s;
}

bool get_bool(const json& j, const std::string& path) {
  if (!j.is_boolean()) fail(path, std::string("must be true or false (got ") + j.type_name() + ")");
  return j.get<bool>();
}

std::string get_choice(const json& j, const std::string& path, std::initializer_list<std::string_view> choices) {
  std::string list;
  for (std::string_view c : choices) {
    if (!list.empty()) list += "|";
    list += c;
  }
  if (!j.is_string()) fail(path, "must be one of " + list + " (got " + j.type_name() + ")");
  const std::string s = j.get<std::string>();
  if (std::find(choices.begin(), choices.end(), s) == choices.end()) {
    fail(path, "must be one of " + list + got(j));
  }
  return s;
}

std::array<double, 3> get_vec3(const json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 3) {
    fail(path, std::string("must be an array of 3 numbers (got ") +
                   (j.is_array() ? std::to_string(j.size()) + " elements" : std::string(j.type_name())) + ")");
  }
  std::array<double, 3> v{};
  for (std::size_t i = 0; i < 3; ++i) v[i] = get_number(j[i], element(path, i));
  return v;
}

glm::vec3 get_colour(const json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 3) {
    fail(path, std::string("must be an array of 3 numbers in [0, 1] (got ") +
                   (j.is_array() ? std::to_string(j.size()) + " elements" : std::string(j.type_name())) + ")");
  }
  glm::vec3 c{};
  for (int i = 0; i < 3; ++i) {
    c[i] = static_cast<float>(get_number_in(j[i], element(path, std::size_t(i)), 0.0, 1.0));
  }
  return c;
}

// Names end up in output file names: keep them to something path-safe.
std::string get_name(const json& j, const std::string& path) {
  std::string s = get_nonempty_string(j, path);
  for (unsigned char c : s) {
    if (c < 0x20 || c == 0x7f || c == '/' || c == '\\') {
      fail(path, "must not contain '/', '\\' or control characters" + got(j));
    }
  }
  if (s == "." || s == "..") fail(path, "must not be \".\" or \"..\"");
  return s;
}

// ---------------------------------------------------------------------------

struct Context {
  std::string base_dir;  // relative file paths are resolved against this; "" = leave as is
};

// A string naming a file: environment variables expanded, then relative paths
// resolved against the scenario file's directory.
std::string get_file_path(const json& j, const std::string& path, const Context& ctx) {
  const std::string raw = get_nonempty_string(j, path);
  std::string expanded;
  try {
    expanded = expand_env(raw);
  } catch (const ScenarioError& e) {
    fail(path, e.what());
  }
  if (expanded.empty()) fail(path, "is empty after expanding environment variables" + got(j));
  fs::path p(expanded);
  if (p.is_relative() && !ctx.base_dir.empty()) p = fs::path(ctx.base_dir) / p;
  return p.lexically_normal().string();
}

GeneratorSpec parse_generator(const json& j, const std::string& path) {
  require_object(j, path);
  check_keys(j, path, {"size", "seed", "spacing_m", "relief_m", "base_m", "octaves", "ridge_weight", "origin"});
  GeneratorSpec g;
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

TerrainSpec parse_terrain(const json& j, const Context& ctx) {
  const std::string path = "terrain";
  require_object(j, path);
  check_keys(j, path, {"file", "encoding", "scale", "offset", "spacing_m", "generator", "height_window", "texture_limit",
                     "memory_budget_mb", "imagery_budget_mb", "wait_for_pages", "vertical_datum", "void_fill"});
  const bool has_file = j.contains("file");
  const bool has_gen = j.contains("generator");
  if (has_file && has_gen) fail(path, "exactly one of \"file\" or \"generator\" may be given, not both");
  if (!has_file && !has_gen) fail(path, "exactly one of \"file\" or \"generator\" is required");

  TerrainSpec t;
  if (j.contains("height_window"))
    t.height_window = static_cast<int>(get_integer(j["height_window"], child(path, "height_window"), 0, 16384));
  if (j.contains("texture_limit"))
    t.texture_limit = static_cast<int>(get_integer(j["texture_limit"], child(path, "texture_limit"), 0, 1 << 20));
  if (j.contains("vertical_datum"))
    t.vertical_datum = get_choice(j["vertical_datum"], child(path, "vertical_datum"), {"geoid", "ellipsoid"});
  if (j.contains("wait_for_pages")) t.wait_for_pages = get_bool(j["wait_for_pages"], child(path, "wait_for_pages"));
  if (j.contains("memory_budget_mb"))
    t.memory_budget_mb =
        static_cast<int>(get_integer(j["memory_budget_mb"], child(path, "memory_budget_mb"), 1, 1 << 20));
  if (j.contains("imagery_budget_mb"))
    t.imagery_budget_mb =
        static_cast<int>(get_integer(j["imagery_budget_mb"], child(path, "imagery_budget_mb"), 1, 1 << 20));
  if (has_gen) {
    for (const char* k : {"encoding", "scale", "offset", "spacing_m", "vertical_datum", "void_fill"}) {
      if (j.contains(k)) {
        fail(child(path, k), "only allowed with terrain.file (generator settings go in terrain.generator)");
      }
    }
    t.generator = parse_generator(j["generator"], child(path, "generator"));
    return t;
  }
  t.file = get_file_path(j["file"], child(path, "file"), ctx);
  if (j.contains("encoding")) t.encoding = get_choice(j["encoding"], child(path, "encoding"), {"auto", "terrain-rgb", "png16"});
  if (j.contains("scale")) {
    const std::string p = child(path, "scale");
    t.scale = get_number_in(j["scale"], p, -1e6, 1e6);
    if (t.scale == 0.0) fail(p, "must not be 0");
  }
  if (j.contains("offset")) t.offset = get_number_in(j["offset"], child(path, "offset"), -1e6, 1e6);
  if (j.contains("spacing_m")) t.spacing_m = get_positive(j["spacing_m"], child(path, "spacing_m"), 1e5);
  if (j.contains("void_fill")) t.void_fill = parse_void_fill(j["void_fill"], child(path, "void_fill"));
  return t;
}

options::TwoLevelOptions parse_twolevel(const json& j, const std::string& path) {
  require_object(j, path);
  check_keys(j, path, {"level0_budget", "a1", "a2", "alpha", "beta", "max_level1", "band_stride", "band", "eye_guard", "level0_envelope", "level0_error", "predict_size", "horizon_culling"});
  options::TwoLevelOptions t;
  if (j.contains("level0_budget")) {
    const auto& b = j["level0_budget"];
    t.level0_budget = b.is_string() && b.get<std::string>() == "auto"
                          ? 0
                          : static_cast<int>(get_integer(b, child(path, "level0_budget") + " (a number or \"auto\")",
                                                        options::TwoLevelOptions::kMinLevel0Budget,
                                                        options::TwoLevelOptions::kMaxLevel0Budget));
  }
  if (j.contains("a1")) t.a1 = get_number(j["a1"], child(path, "a1"));
  if (j.contains("a2")) t.a2 = get_number(j["a2"], child(path, "a2"));
  if (const auto why = options::TwoLevelOptions::check_thresholds(t.a1, t.a2))  // "aN must ..."
    fail(child(path, why->substr(0, 2)), why->substr(3));
  if (j.contains("alpha")) t.alpha = get_positive(j["alpha"], child(path, "alpha"), options::TwoLevelOptions::kMaxAlpha);
  if (j.contains("beta"))
    t.gaussian_beta = get_choice(j["beta"], child(path, "beta"), {"linear", "gaussian"}) == "gaussian";
  if (j.contains("max_level1")) {
    const std::string p = child(path, "max_level1");
    const long long n = get_integer(j["max_level1"], p, 33, 1025);
    if (((n - 1) & (n - 2)) != 0) fail(p, "must be one of 33, 65, 129, 257, 513, 1025" + got(j["max_level1"]));
    t.max_level1 = static_cast<int>(n);
  }
  if (j.contains("band_stride")) t.band_stride = static_cast<int>(get_integer(j["band_stride"], child(path, "band_stride"), 1, 64));
  if (j.contains("band")) t.band_inline = get_choice(j["band"], child(path, "band"), {"inline", "target"}) == "inline";
  if (j.contains("level0_error"))
    t.level0_whole_error = get_choice(j["level0_error"], child(path, "level0_error"), {"midpoint", "whole"}) == "whole";
  if (j.contains("eye_guard")) t.eye_guard = get_bool(j["eye_guard"], child(path, "eye_guard"));
  if (j.contains("level0_envelope"))
    t.level0_envelope = get_bool(j["level0_envelope"], child(path, "level0_envelope"));
  if (j.contains("predict_size")) t.predict_size = get_bool(j["predict_size"], child(path, "predict_size"));
  if (j.contains("horizon_culling")) t.horizon_culling = get_bool(j["horizon_culling"], child(path, "horizon_culling"));
  return t;
}

RenderSpec parse_render(const json& j, const Context& ctx) {
  const std::string path = "render";
  require_object(j, path);
  check_keys(j, path,
             {"width", "height", "fov_y_deg", "near_m", "far_m", "method", "fog_visibility_m", "sky_zenith_rgb",
              "sky_horizon_rgb", "sun_direction", "imagery", "frame_budget_ms", "vsync", "earth_curvature", "twolevel",
              "ground_detail", "antialiasing", "msaa_samples"});
  RenderSpec r;
  if (j.contains("width")) r.width = static_cast<int>(get_integer(j["width"], child(path, "width"), 1, kMaxImageSide));
  if (j.contains("height")) r.height = static_cast<int>(get_integer(j["height"], child(path, "height"), 1, kMaxImageSide));
  if (j.contains("fov_y_deg")) {
    const std::string p = child(path, "fov_y_deg");
    r.fov_y_deg = get_number(j["fov_y_deg"], p);
    if (!(r.fov_y_deg > 0.0 && r.fov_y_deg <= 179.0)) fail(p, "must be in (0, 179]" + got(j["fov_y_deg"]));
  }
  if (j.contains("near_m")) r.near_m = get_positive(j["near_m"], child(path, "near_m"), kMaxDistanceM);
  if (j.contains("far_m")) r.far_m = get_positive(j["far_m"], child(path, "far_m"), kMaxDistanceM);
  if (!(r.far_m > r.near_m)) {
    fail(child(path, "far_m"), "must be > render.near_m (far_m " + num(r.far_m) + ", near_m " + num(r.near_m) + ")");
  }
  if (j.contains("method")) r.method = get_nonempty_string(j["method"], child(path, "method"));
  if (j.contains("fog_visibility_m")) {
    r.shading.fog_visibility_m = get_number_in(j["fog_visibility_m"], child(path, "fog_visibility_m"), 0.0,
                                                 options::ShadingOptions::kMaxFogVisibilityM);
  }
  if (j.contains("sky_zenith_rgb")) r.shading.sky_zenith = get_colour(j["sky_zenith_rgb"], child(path, "sky_zenith_rgb"));
  if (j.contains("sky_horizon_rgb"))
    r.shading.sky_horizon = get_colour(j["sky_horizon_rgb"], child(path, "sky_horizon_rgb"));
  if (j.contains("sun_direction")) {
    const std::string p = child(path, "sun_direction");
    std::array<double, 3> v = get_vec3(j["sun_direction"], p);
    const double m = std::max({std::fabs(v[0]), std::fabs(v[1]), std::fabs(v[2])});
    if (!(m > 1e-12)) fail(p, "must be a non-zero vector" + got(j["sun_direction"]));
    // Scale first so squaring cannot overflow, then normalise.
    for (double& c : v) c /= m;
    const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    r.shading.sun_direction = glm::vec3(float(v[0] / len), float(v[1] / len), float(v[2] / len));
  }
  if (j.contains("imagery")) r.imagery = get_file_path(j["imagery"], child(path, "imagery"), ctx);
  if (j.contains("frame_budget_ms")) r.frame_budget_ms = get_positive(j["frame_budget_ms"], child(path, "frame_budget_ms"), 1e6);
  if (j.contains("vsync")) r.vsync = get_bool(j["vsync"], child(path, "vsync"));
  if (j.contains("earth_curvature"))
    r.earth_curvature = get_choice(j["earth_curvature"], child(path, "earth_curvature"), {"auto", "on", "off"});
  if (j.contains("twolevel")) r.twolevel = parse_twolevel(j["twolevel"], child(path, "twolevel"));
  if (j.contains("ground_detail")) r.shading.ground_detail = get_bool(j["ground_detail"], child(path, "ground_detail"));
  if (j.contains("antialiasing"))
    r.antialiasing = get_choice(j["antialiasing"], child(path, "antialiasing"), {"auto", "msaa", "fxaa", "off"});
  if (j.contains("msaa_samples"))
    r.msaa_samples = static_cast<int>(get_integer(j["msaa_samples"], child(path, "msaa_samples"), 2, 64));
  return r;
}

// environment: the scene's date and time (the sun follows them).
void parse_environment(const json& j, options::ShadingOptions& shading) {
  const std::string path = "environment";
  require_object(j, path);
  check_keys(j, path, {"time_utc"});
  if (j.contains("time_utc")) {
    const std::string p = child(path, "time_utc");
    std::string why;
    const auto t = parse_utc_time(get_string(j["time_utc"], p), why);
    if (!t) fail(p, why + got(j["time_utc"]));
    shading.time_utc = *t;
  }
}

std::vector<ChannelSpec> parse_channels(const json& j) {
  const std::string path = "channels";
  require_array(j, path);
  if (j.empty()) fail(path, "must contain at least one channel (omit \"channels\" for a single \"main\" channel)");
  std::vector<ChannelSpec> out;
  std::set<std::string> names;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string p = element(path, i);
    const json& c = j[i];
    require_object(c, p);
    check_keys(c, p, {"name", "heading_offset_deg", "pitch_offset_deg", "roll_offset_deg", "fov_y_deg"});
    ChannelSpec ch;
    ch.name = i == 0 ? "main" : "channel" + std::to_string(i);
    if (c.contains("name")) ch.name = get_name(c["name"], child(p, "name"));
    if (!names.insert(ch.name).second) fail(child(p, "name"), "duplicate channel name \"" + ch.name + "\"");
    if (c.contains("heading_offset_deg")) {
      ch.heading_offset_deg = get_number_in(c["heading_offset_deg"], child(p, "heading_offset_deg"), -360.0, 360.0);
    }
    if (c.contains("pitch_offset_deg")) {
      ch.pitch_offset_deg = get_number_in(c["pitch_offset_deg"], child(p, "pitch_offset_deg"), -90.0, 90.0);
    }
    if (c.contains("roll_offset_deg")) {
      ch.roll_offset_deg = get_number_in(c["roll_offset_deg"], child(p, "roll_offset_deg"), -180.0, 180.0);
    }
    if (c.contains("fov_y_deg")) {
      const std::string fp = child(p, "fov_y_deg");
      const double f = get_number(c["fov_y_deg"], fp);
      if (!(f > 0.0 && f <= 179.0)) fail(fp, "must be in (0, 179]" + got(c["fov_y_deg"]));
      ch.fov_y_deg = f;
    }
    out.push_back(std::move(ch));
  }
  return out;
}

PathSpec parse_path(const json& j) {
  const std::string path = "path";
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

// Tracks keys while nlohmann parses so that a repeated key in one object
// (which nlohmann would silently resolve to the last value) is an error.
class DuplicateKeyCheck {
 public:
  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
        note_element();
        stack_.push_back(Frame{false, -1, {}, {}});
        break;
      case json::parse_event_t::array_start:
        note_element();
        stack_.push_back(Frame{true, -1, {}, {}});
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        if (!stack_.empty()) stack_.pop_back();
        break;
      case json::parse_event_t::key: {
        if (stack_.empty()) break;
        const std::string key = parsed.get<std::string>();
        Frame& f = stack_.back();
        if (!f.keys.insert(key).second) fail(child(parent_path(), key), "duplicate key");
        f.key = key;
        break;
      }
      case json::parse_event_t::value:
        note_element();
        break;
    }
    return true;
  }

 private:
  struct Frame {
    bool is_array;
    long index;
    std::string key;
    std::set<std::string> keys;
  };

  void note_element() {
    if (!stack_.empty() && stack_.back().is_array) ++stack_.back().index;
  }

  // Key path of the innermost open object.
  std::string parent_path() const {
    std::string p;
    for (std::size_t i = 0; i + 1 < stack_.size(); ++i) {
      const Frame& f = stack_[i];
      p = f.is_array ? element(p, static_cast<std::size_t>(f.index)) : child(p, f.key);
    }
    return p;
  }

  std::vector<Frame> stack_;
};

// "syntax error while parsing value - unexpected '}'" out of nlohmann's
// "[json.exception.parse_error.101] parse error at line 2, column 7: ...".
std::string parse_error_reason(const std::string& what) {
  const std::size_t col = what.find("column ");
  if (col != std::string::npos) {
    const std::size_t colon = what.find(": ", col);
    if (colon != std::string::npos) return what.substr(colon + 2);
  }
  const std::size_t bracket = what.find("] ");
  return bracket != std::string::npos ? what.substr(bracket + 2) : what;
}

Scenario parse_impl(const std::string& text, const std::string& origin, const Context& ctx,
                    const std::string& default_name) {
  json root;
  try {
    DuplicateKeyCheck dup;
    root = json::parse(text, std::ref(dup));
  } catch (const json::parse_error& e) {
    // e.byte: 1-based index of the character where parsing stopped.
    const std::size_t end = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < end; ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    throw ScenarioError(origin + ": invalid JSON at line " + std::to_string(line) + ", column " +
                        std::to_string(column) + " (byte " + std::to_string(e.byte) +
                        "): " + parse_error_reason(e.what()));
  } catch (const json::exception& e) {
    // e.g. out_of_range.406 "number overflow parsing '1e400'".
    throw ScenarioError(origin + ": invalid JSON: " + parse_error_reason(e.what()));
  } catch (const ScenarioError& e) {
    throw ScenarioError(origin + ": " + e.what());
  }

  try {
    if (!root.is_object()) {
      throw ScenarioError(std::string("top level must be a JSON object (got ") + root.type_name() + ")");
    }
    check_keys(root, "", {"name", "terrain", "render", "environment", "channels", "path", "time", "capture", "live"});

    Scenario s;
    s.name = root.contains("name") ? get_name(root["name"], "name") : default_name;
    if (!root.contains("terrain")) fail("terrain", "required key is missing");
    s.terrain = parse_terrain(root["terrain"], ctx);
    if (root.contains("render")) s.render = parse_render(root["render"], ctx);
    if (root.contains("environment")) parse_environment(root["environment"], s.render.shading);
    if (root.contains("channels")) {
      s.channels = parse_channels(root["channels"]);
    } else {
      s.channels.push_back(ChannelSpec{});
    }
    if (!root.contains("path")) fail("path", "required key is missing");
    s.path = parse_path(root["path"]);

    s.duration_s = s.path.keys.back().t_s;
    if (root.contains("time")) {
      const json& t = root["time"];
      require_object(t, "time");
      check_keys(t, "time", {"step_s", "duration_s"});
      if (t.contains("step_s")) {
        const double step = get_number(t["step_s"], "time.step_s");
        if (!(step > 0.0 && step <= 1.0)) fail("time.step_s", "must be in (0, 1]" + got(t["step_s"]));
        s.time_step_s = step;
      }
      if (t.contains("duration_s")) s.duration_s = get_number_in(t["duration_s"], "time.duration_s", 0.0, kMaxTimeS);
    }
    const double frames = std::floor(s.duration_s / s.time_step_s + 1e-9) + 1.0;
    if (frames > static_cast<double>(kMaxFrames)) {
      fail("time", "duration_s / step_s gives " + num(frames) + " frames; at most " + std::to_string(kMaxFrames) +
                       " are allowed");
    }

    if (root.contains("capture")) {
      const json& c = root["capture"];
      require_object(c, "capture");
      check_keys(c, "capture", {"times_s", "every_s"});
      if (c.contains("times_s")) {
        const json& ts = c["times_s"];
        require_array(ts, "capture.times_s");
        for (std::size_t i = 0; i < ts.size(); ++i) {
          const std::string p = element("capture.times_s", i);
          const double v = get_number(ts[i], p);
          if (!(v >= 0.0 && v <= s.duration_s)) {
            fail(p, "must be within [0, duration_s] = [0, " + num(s.duration_s) + "]" + got(ts[i]));
          }
          s.capture_times_s.push_back(v);
        }
      }
      if (c.contains("every_s")) {
        const double every = get_positive(c["every_s"], "capture.every_s", kMaxTimeS);
        if (every < s.time_step_s)
          fail("capture.every_s", "must be >= time.step_s (" + num(s.time_step_s) +
                                      "): one capture a frame is the most there can be" + got(c["every_s"]));
        s.capture_every_s = every;
      }
    }
    if (root.contains("live")) {
      const json& l = root["live"];
      require_object(l, "live");
      check_keys(l, "live", {"latency"});
      if (l.contains("latency")) {
        const auto m = parse_latency_mode(get_string(l["latency"], "live.latency"));
        if (!m) fail("live.latency", "must be \"smooth\", \"latest\" or \"sync\"" + got(l["latency"]));
        s.live_latency = *m;
      }
    }
    return s;
  } catch (const ScenarioError& e) {
    throw ScenarioError(origin + ": " + e.what());
  }
}

bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

}  // namespace

std::string expand_env(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c != '$' || i + 1 >= text.size()) {
      out += c;
      ++i;
      continue;
    }
    std::string name;
    std::size_t next;
    if (text[i + 1] == '{') {
      const std::size_t close = text.find('}', i + 2);
      if (close == std::string::npos) throw ScenarioError("unterminated \"${\" in \"" + text + "\"");
      name = text.substr(i + 2, close - (i + 2));
      const bool valid = !name.empty() && is_name_start(name[0]) &&
                         std::all_of(name.begin(), name.end(), [](char ch) { return is_name_char(ch); });
      if (!valid) throw ScenarioError("invalid environment variable name \"" + name + "\" in \"" + text + "\"");
      next = close + 1;
    } else if (is_name_start(text[i + 1])) {
      std::size_t e = i + 1;
      while (e < text.size() && is_name_char(text[e])) ++e;
      name = text.substr(i + 1, e - (i + 1));
      next = e;
    } else {
      out += c;  // a lone '$' is kept as is
      ++i;
      continue;
    }
    const char* value = std::getenv(name.c_str());
    if (value == nullptr) throw ScenarioError("environment variable " + name + " is not set");
    out += value;
    i = next;
  }
  return out;
}

Scenario parse_scenario(const std::string& json_text, const std::string& origin) {
  return parse_impl(json_text, origin, Context{}, "scenario");
}

Scenario load_scenario(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int err = errno;
    throw ScenarioError(path + ": cannot open scenario file" + (err != 0 ? std::string(": ") + std::strerror(err) : ""));
  }
  std::ostringstream buf;
  buf << in.rdbuf();
  if (in.bad()) throw ScenarioError(path + ": error reading scenario file");

  Context ctx;
  std::error_code ec;
  fs::path dir = fs::absolute(fs::path(path), ec).parent_path();
  if (ec) dir = fs::path(path).parent_path();
  ctx.base_dir = dir.empty() ? std::string(".") : dir.string();

  std::string stem = fs::path(path).stem().string();
  if (stem.empty()) stem = "scenario";
  Scenario s = parse_impl(buf.str(), path, ctx, stem);
  s.source_path = path;
  return s;
}

int scenario_frame_count(const Scenario& s) {
  if (!(s.time_step_s > 0.0) || !std::isfinite(s.time_step_s) || !(s.duration_s >= 0.0) ||
      !std::isfinite(s.duration_s)) {
    throw ScenarioError("scenario_frame_count: time step must be > 0 and duration >= 0");
  }
  const double frames = std::floor(s.duration_s / s.time_step_s + 1e-9) + 1.0;
  if (frames >= static_cast<double>(INT_MAX)) return INT_MAX;
  return static_cast<int>(frames);
}

}  // namespace ig::io
