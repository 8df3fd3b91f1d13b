// The scenario file parser (schema: docs/scenario.md): one function per
// section in the schema's order. Every key goes through the same checks and
// error wording (scenario_json.h); the terrain generator / void fill, the path and
// the per-method sections are parsed in scenario_terrain.cpp,
// scenario_path.cpp and scenario_methods.cpp.
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

#include "io/scenario_json.h"
#include "io/utc_time.h"

namespace ig::io {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

using namespace scenario_json;

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

TerrainSpec parse_terrain(const json& j, const Context& ctx) {
  const std::string path = "terrain";
  require_object(j, path);
  check_keys(j, path, {"file", "encoding", "scale", "offset", "spacing_m", "generator", "height_window", "texture_limit",
                     "memory_budget_mb", "imagery_budget_mb", "wait_for_pages", "vertical_datum", "void_fill", "water"});
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
  if (j.contains("water"))
    t.water = parse_water(j["water"], child(path, "water"),
                          [&ctx](const json& v, const std::string& p) { return get_file_path(v, p, ctx); });
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

RenderSpec parse_render(const json& j, const Context& ctx) {
  const std::string path = "render";
  require_object(j, path);
  check_keys(j, path,
             {"width", "height", "fov_y_deg", "near_m", "far_m", "method", "fog_visibility_m", "sky_zenith_rgb",
              "sky_horizon_rgb", "sun_direction", "imagery", "frame_budget_ms", "vsync", "earth_curvature", "twolevel",
              "roam", "quadtree", "geomipmap", "chunked", "cdlod", "ground_detail", "deferred_shading", "antialiasing",
              "msaa_samples"});
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
  parse_method_options(j, path, r);
  if (j.contains("ground_detail")) r.shading.ground_detail = get_bool(j["ground_detail"], child(path, "ground_detail"));
  if (j.contains("deferred_shading"))
    r.shading.deferred_shading = get_bool(j["deferred_shading"], child(path, "deferred_shading"));
  if (j.contains("antialiasing"))
    r.antialiasing = get_choice(j["antialiasing"], child(path, "antialiasing"), {"auto", "msaa", "fxaa", "off"});
  if (j.contains("msaa_samples"))
    r.msaa_samples = static_cast<int>(get_integer(j["msaa_samples"], child(path, "msaa_samples"), 2, 64));
  return r;
}

// environment: the scene's date and time (the sun follows them) and its clouds.
void parse_environment(const json& j, options::ShadingOptions& shading) {
  const std::string path = "environment";
  require_object(j, path);
  check_keys(j, path, {"time_utc", "clouds"});
  if (j.contains("clouds")) shading.clouds = parse_clouds(j["clouds"], child(path, "clouds"));
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
    check_keys(root, "",
               {"name", "terrain", "render", "environment", "channels", "path", "entities", "time", "capture", "live"});

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
    if (root.contains("entities")) s.entities = parse_entities(root["entities"]);

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
    // An empty value would turn "${DIR}/file" into "/file": never what was meant.
    if (*value == '\0') throw ScenarioError("environment variable " + name + " is set but empty (in \"" + text + "\")");
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
