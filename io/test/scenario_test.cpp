#include "io/scenario.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scenario_error.h"

namespace {

namespace fs = std::filesystem;
using namespace ig::io;

// Message of the ScenarioError that parsing `text` throws; fails the test
// (and returns "") when it parses.
// A minimal valid document with `extra` spliced in at top level (which may
// replace "terrain"/"path" when `terrain`/`path` are given).
std::string doc(const std::string& extra = "", const std::string& terrain = R"({"generator": {"size": 257}})",
                const std::string& path = R"({"keys": [{"t": 0, "position": [0, 0, 100]}, {"t": 4, "position": [100, 0, 100]}]})") {
  std::string s = "{\n  \"terrain\": " + terrain + ",\n  \"path\": " + path;
  if (!extra.empty()) s += ",\n  " + extra;
  return s + "\n}\n";
}

class TempDir {
 public:
  TempDir() {
    path_ = fs::temp_directory_path() /
            ("ig_scenario_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter_++));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }
  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path p = path_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p;
  }

 private:
  static inline int counter_ = 0;
  fs::path path_;
};

const char* kFull = R"({
  "name": "valley_run",
  "terrain": { "file": "/data/dem/sierra.tif", "encoding": "png16", "scale": 0.1, "offset": -500, "spacing_m": 25 },
  "render": { "width": 1280, "height": 720, "fov_y_deg": 50, "near_m": 1.5, "far_m": 200000, "method": "tessellated",
              "fog_visibility_m": 40000, "sky_zenith_rgb": [0.1, 0.2, 0.3], "sky_horizon_rgb": [0.4, 0.5, 0.6],
              "sun_direction": [0, 3, 4], "imagery": "/data/ortho.png", "frame_budget_ms": 8.333, "vsync": false },
  "channels": [
    { "name": "left", "heading_offset_deg": -60, "pitch_offset_deg": -5, "roll_offset_deg": 2, "fov_y_deg": 45 },
    { "name": "centre" },
    { "name": "right", "heading_offset_deg": 60 }
  ],
  "path": { "frame": "geodetic", "altitude": "agl",
            "keys": [ { "t": 0, "position": [37.5, -119.25, 300], "hpr": [350, 2, -3] },
                      { "t": 2.5, "position": [37.51, -119.24, 320], "hpr": [10, 0, 15] },
                      { "t": 9, "position": [37.6, -119.1, 500] } ] },
  "time": { "step_s": 0.02, "duration_s": 8 },
  "capture": { "times_s": [0, 4.5, 8] }
})";

TEST(Scenario, FullDocumentEveryField) {
  const Scenario s = parse_scenario(kFull);
  EXPECT_EQ(s.name, "valley_run");
  EXPECT_EQ(s.source_path, "");
  ASSERT_TRUE(s.terrain.file.has_value());
  EXPECT_EQ(*s.terrain.file, "/data/dem/sierra.tif");
  EXPECT_FALSE(s.terrain.generator.has_value());
  EXPECT_EQ(s.terrain.encoding, "png16");
  EXPECT_DOUBLE_EQ(s.terrain.scale, 0.1);
  EXPECT_DOUBLE_EQ(s.terrain.offset, -500.0);
  ASSERT_TRUE(s.terrain.spacing_m.has_value());
  EXPECT_DOUBLE_EQ(*s.terrain.spacing_m, 25.0);

  EXPECT_EQ(s.render.width, 1280);
  EXPECT_EQ(s.render.height, 720);
  EXPECT_DOUBLE_EQ(s.render.fov_y_deg, 50.0);
  EXPECT_DOUBLE_EQ(s.render.near_m, 1.5);
  EXPECT_DOUBLE_EQ(s.render.far_m, 200000.0);
  EXPECT_EQ(s.render.method, "tessellated");
  EXPECT_DOUBLE_EQ(s.render.shading.fog_visibility_m, 40000.0);
  EXPECT_FLOAT_EQ(s.render.shading.sky_zenith[0], 0.1f);
  EXPECT_FLOAT_EQ(s.render.shading.sky_zenith[1], 0.2f);
  EXPECT_FLOAT_EQ(s.render.shading.sky_zenith[2], 0.3f);
  EXPECT_FLOAT_EQ(s.render.shading.sky_horizon[0], 0.4f);
  EXPECT_FLOAT_EQ(s.render.shading.sky_horizon[1], 0.5f);
  EXPECT_FLOAT_EQ(s.render.shading.sky_horizon[2], 0.6f);
  // Normalised.
  ASSERT_TRUE(s.render.shading.sun_direction.has_value());
  EXPECT_FLOAT_EQ(s.render.shading.sun_direction->x, 0.0f);
  EXPECT_FLOAT_EQ(s.render.shading.sun_direction->y, 0.6f);
  EXPECT_FLOAT_EQ(s.render.shading.sun_direction->z, 0.8f);
  ASSERT_TRUE(s.render.imagery.has_value());
  EXPECT_EQ(*s.render.imagery, "/data/ortho.png");
  EXPECT_DOUBLE_EQ(s.render.frame_budget_ms, 8.333);
  EXPECT_FALSE(s.render.vsync);

  ASSERT_EQ(s.channels.size(), 3u);
  EXPECT_EQ(s.channels[0].name, "left");
  EXPECT_DOUBLE_EQ(s.channels[0].heading_offset_deg, -60.0);
  EXPECT_DOUBLE_EQ(s.channels[0].pitch_offset_deg, -5.0);
  EXPECT_DOUBLE_EQ(s.channels[0].roll_offset_deg, 2.0);
  ASSERT_TRUE(s.channels[0].fov_y_deg.has_value());
  EXPECT_DOUBLE_EQ(*s.channels[0].fov_y_deg, 45.0);
  EXPECT_EQ(s.channels[1].name, "centre");
  EXPECT_DOUBLE_EQ(s.channels[1].heading_offset_deg, 0.0);
  EXPECT_FALSE(s.channels[1].fov_y_deg.has_value());
  EXPECT_EQ(s.channels[2].name, "right");
  EXPECT_DOUBLE_EQ(s.channels[2].heading_offset_deg, 60.0);

  EXPECT_EQ(s.path.frame, PositionFrame::Geodetic);
  EXPECT_EQ(s.path.altitude, AltitudeMode::AboveGround);
  ASSERT_EQ(s.path.keys.size(), 3u);
  EXPECT_DOUBLE_EQ(s.path.keys[0].t_s, 0.0);
  EXPECT_DOUBLE_EQ(s.path.keys[0].position[0], 37.5);
  EXPECT_DOUBLE_EQ(s.path.keys[0].position[1], -119.25);
  EXPECT_DOUBLE_EQ(s.path.keys[0].position[2], 300.0);
  EXPECT_DOUBLE_EQ(s.path.keys[0].heading_deg, 350.0);
  EXPECT_DOUBLE_EQ(s.path.keys[0].pitch_deg, 2.0);
  EXPECT_DOUBLE_EQ(s.path.keys[0].roll_deg, -3.0);
  EXPECT_DOUBLE_EQ(s.path.keys[1].t_s, 2.5);
  EXPECT_DOUBLE_EQ(s.path.keys[1].roll_deg, 15.0);
  EXPECT_DOUBLE_EQ(s.path.keys[2].t_s, 9.0);
  EXPECT_DOUBLE_EQ(s.path.keys[2].heading_deg, 0.0);  // hpr omitted
  EXPECT_DOUBLE_EQ(s.path.keys[2].pitch_deg, 0.0);
  EXPECT_DOUBLE_EQ(s.path.keys[2].roll_deg, 0.0);

  EXPECT_DOUBLE_EQ(s.time_step_s, 0.02);
  EXPECT_DOUBLE_EQ(s.duration_s, 8.0);
  EXPECT_EQ(s.capture_times_s, (std::vector<double>{0.0, 4.5, 8.0}));
  EXPECT_EQ(scenario_frame_count(s), 401);
}

TEST(Scenario, GeneratorEveryField) {
  const Scenario s = parse_scenario(doc("", R"({"generator": {"size": 1025, "seed": 7, "spacing_m": 30,
      "relief_m": 1800, "base_m": 200, "octaves": 9, "ridge_weight": 0.55}})"));
  ASSERT_TRUE(s.terrain.generator.has_value());
  EXPECT_FALSE(s.terrain.file.has_value());
  const auto& g = *s.terrain.generator;
  EXPECT_EQ(g.size, 1025);
  EXPECT_EQ(g.seed, 7u);
  EXPECT_DOUBLE_EQ(g.spacing_m, 30.0);
  EXPECT_DOUBLE_EQ(g.relief_m, 1800.0);
  EXPECT_DOUBLE_EQ(g.base_m, 200.0);
  EXPECT_EQ(g.octaves, 9);
  EXPECT_DOUBLE_EQ(g.ridge_weight, 0.55);
  // Largest seed fits an unsigned.
  EXPECT_EQ(parse_scenario(doc("", R"({"generator": {"seed": 4294967295}})")).terrain.generator->seed, 4294967295u);
}

TEST(Scenario, Defaults) {
  const Scenario s = parse_scenario(doc("", R"({"generator": {}})"));
  const ig::options::SyntheticTerrainOptions g0;
  EXPECT_EQ(s.terrain.generator->size, g0.size);
  EXPECT_EQ(s.terrain.generator->seed, g0.seed);
  EXPECT_EQ(s.name, "scenario");
  const ig::io::RenderSpec r0;
  EXPECT_EQ(s.render.width, r0.width);
  EXPECT_EQ(s.render.height, r0.height);
  EXPECT_EQ(s.render.fov_y_deg, r0.fov_y_deg);
  EXPECT_EQ(s.render.near_m, r0.near_m);
  EXPECT_EQ(s.render.far_m, r0.far_m);
  EXPECT_EQ(s.render.method, r0.method);
  EXPECT_EQ(s.render.shading.fog_visibility_m, r0.shading.fog_visibility_m);
  EXPECT_EQ(s.render.shading.sky_zenith, r0.shading.sky_zenith);
  EXPECT_EQ(s.render.shading.sky_horizon, r0.shading.sky_horizon);
  EXPECT_EQ(s.render.shading.sun_direction, r0.shading.sun_direction);
  EXPECT_TRUE(s.render.shading.deferred_shading);
  EXPECT_FALSE(s.render.imagery.has_value());
  EXPECT_EQ(s.render.frame_budget_ms, r0.frame_budget_ms);
  EXPECT_EQ(s.render.vsync, r0.vsync);
  ASSERT_EQ(s.channels.size(), 1u);
  EXPECT_EQ(s.channels[0].name, "main");
  EXPECT_EQ(s.channels[0].heading_offset_deg, 0.0);
  EXPECT_EQ(s.channels[0].pitch_offset_deg, 0.0);
  EXPECT_EQ(s.channels[0].roll_offset_deg, 0.0);
  EXPECT_FALSE(s.channels[0].fov_y_deg.has_value());
  EXPECT_EQ(s.path.frame, PositionFrame::Local);
  EXPECT_EQ(s.path.altitude, AltitudeMode::AboveSeaLevel);
  EXPECT_DOUBLE_EQ(s.time_step_s, 1.0 / 60.0);
  EXPECT_DOUBLE_EQ(s.duration_s, 4.0);  // last key time
  EXPECT_TRUE(s.capture_times_s.empty());
  EXPECT_EQ(s.capture_every_s, 0.0);
  EXPECT_EQ(parse_scenario(doc(R"("capture": {"every_s": 1.5})")).capture_every_s, 1.5);
  EXPECT_EQ(s.live_latency, LatencyMode::Smooth);
  EXPECT_EQ(scenario_frame_count(s), 241);
  EXPECT_EQ(parse_scenario(doc(R"("live": {"latency": "latest"})")).live_latency, LatencyMode::Latest);

  // Unnamed channels after the first get distinct names.
  const Scenario c = parse_scenario(doc(R"("channels": [{}, {"heading_offset_deg": 30}])"));
  EXPECT_EQ(c.channels[0].name, "main");
  EXPECT_EQ(c.channels[1].name, "channel1");
  // Integral floats are fine for integer fields.
  EXPECT_EQ(parse_scenario(doc(R"("render": {"width": 800.0})")).render.width, 800);
}

TEST(Scenario, TerrainDatumAndPaging) {
  const Scenario d = parse_scenario(doc("", R"({"file": "x.tif"})"));
  EXPECT_EQ(d.terrain.vertical_datum, "geoid");
  EXPECT_FALSE(d.terrain.wait_for_pages);
  const Scenario s = parse_scenario(doc("", R"({"file": "x.tif", "vertical_datum": "ellipsoid", "wait_for_pages": true})"));
  EXPECT_EQ(s.terrain.vertical_datum, "ellipsoid");
  EXPECT_TRUE(s.terrain.wait_for_pages);
}

TEST(Scenario, FrameCount) {
  Scenario s;
  s.time_step_s = 0.0166667;
  s.duration_s = 12;
  EXPECT_EQ(scenario_frame_count(s), 720);  // 12 / 0.0166667 = 719.9986
  s.time_step_s = 1.0 / 60.0;
  EXPECT_EQ(scenario_frame_count(s), 721);
  s.time_step_s = 0.1;
  s.duration_s = 0.3;  // 2.9999999999999996 steps: the epsilon makes it 3
  EXPECT_EQ(scenario_frame_count(s), 4);
  s.duration_s = 0.0;
  EXPECT_EQ(scenario_frame_count(s), 1);
}

struct ErrorCase {
  const char* label;
  std::string text;
  std::vector<std::string> expect;  // substrings of the message
};

TEST(Scenario, ErrorsNameTheirKey) {
  const std::vector<ErrorCase> cases = {
      {"unknown top-level key", doc(R"("colour": 1)"), {"colour: unknown key"}},
      {"unknown nested key", doc(R"("render": {"fov_deg": 60})"), {"render.fov_deg: unknown key"}},
      {"unknown key in generator", doc("", R"({"generator": {"sise": 257}})"), {"terrain.generator.sise: unknown key"}},
      {"unknown key in a path key", doc("", R"({"generator": {}})", R"({"keys": [{"t": 0, "position": [0,0,0], "hdg": 3}]})"),
       {"path.keys[0].hdg: unknown key"}},
      {"unknown key in a channel", doc(R"("channels": [{"name": "a"}, {"name": "b", "fov": 3}])"), {"channels[1].fov: unknown key"}},
      {"negative width", doc(R"("render": {"width": -3})"), {"render.width", "1..16384", "-3"}},
      {"zero width", doc(R"("render": {"width": 0})"), {"render.width", "1..16384", "got 0"}},
      {"zero octaves", doc("", R"({"generator": {"octaves": 0}})"), {"terrain.generator.octaves", "1..20"}},
      {"width too big", doc(R"("render": {"width": 16385})"), {"render.width", "1..16384"}},
      {"fractional height", doc(R"("render": {"height": 480.5})"), {"render.height", "integer"}},
      {"width as string", doc(R"("render": {"width": "640"})"), {"render.width", "string"}},
      {"fov 0", doc(R"("render": {"fov_y_deg": 0})"), {"render.fov_y_deg", "(0, 179]"}},
      {"fov 180", doc(R"("render": {"fov_y_deg": 180})"), {"render.fov_y_deg", "(0, 179]"}},
      {"channel fov 0", doc(R"("channels": [{"fov_y_deg": 0}])"), {"channels[0].fov_y_deg", "(0, 179]"}},
      {"near 0", doc(R"("render": {"near_m": 0})"), {"render.near_m", "> 0"}},
      {"far <= near", doc(R"("render": {"near_m": 10, "far_m": 10})"), {"render.far_m", "near_m"}},
      {"empty method", doc(R"("render": {"method": ""})"), {"render.method", "non-empty"}},
      {"colour out of range", doc(R"("render": {"sky_zenith_rgb": [0.1, 1.5, 0.2]})"), {"render.sky_zenith_rgb[1]", "[0, 1]"}},
      {"colour with 2 numbers", doc(R"("render": {"sky_horizon_rgb": [0.1, 0.2]})"), {"render.sky_horizon_rgb", "3 numbers"}},
      {"deferred shading as a string", doc(R"("render": {"deferred_shading": "yes"})"), {"render.deferred_shading", "true or false"}},
      {"zero sun", doc(R"("render": {"sun_direction": [0, 0, 0]})"), {"render.sun_direction", "non-zero"}},
      {"vsync not bool", doc(R"("render": {"vsync": 1})"), {"render.vsync", "true or false"}},
      {"unknown vertical datum", doc("", R"({"file": "x.tif", "vertical_datum": "navd88"})"), {"terrain.vertical_datum", "navd88"}},
      {"vertical datum with a generator", doc("", R"({"generator": {}, "vertical_datum": "ellipsoid"})"),
       {"terrain.vertical_datum", "only allowed with terrain.file"}},
      {"wait_for_pages not bool", doc("", R"({"file": "x.tif", "wait_for_pages": 1})"), {"terrain.wait_for_pages", "true or false"}},
      {"keys not increasing", doc("", R"({"generator": {}})", R"({"keys": [{"t": 0, "position": [0,0,0]}, {"t": 2, "position": [0,0,0]}, {"t": 2, "position": [1,0,0]}]})"),
       {"path.keys[2].t", "strictly increasing"}},
      {"keys decreasing", doc("", R"({"generator": {}})", R"({"keys": [{"t": 3, "position": [0,0,0]}, {"t": 1, "position": [0,0,0]}]})"),
       {"path.keys[1].t", "strictly increasing"}},
      {"empty keys", doc("", R"({"generator": {}})", R"({"keys": []})"), {"path.keys", "at least one"}},
      {"missing keys", doc("", R"({"generator": {}})", R"({"frame": "local"})"), {"path.keys", "missing"}},
      {"missing position", doc("", R"({"generator": {}})", R"({"keys": [{"t": 0}]})"), {"path.keys[0].position", "missing"}},
      {"position with 2 numbers", doc("", R"({"generator": {}})", R"({"keys": [{"t": 0, "position": [1, 2]}]})"),
       {"path.keys[0].position", "3 numbers"}},
      {"pitch out of range", doc("", R"({"generator": {}})", R"({"keys": [{"t": 0, "position": [0,0,0], "hpr": [0, 91, 0]}]})"),
       {"path.keys[0].hpr[1]", "[-90, 90]"}},
      {"latitude out of range", doc("", R"({"generator": {}})", R"({"frame": "geodetic", "keys": [{"t": 0, "position": [91, 0, 0]}]})"),
       {"path.keys[0].position[0]", "[-90, 90]"}},
      {"longitude out of range", doc("", R"({"generator": {}})", R"({"frame": "geodetic", "keys": [{"t": 0, "position": [0, 360, 0]}]})"),
       {"path.keys[0].position[1]", "[-180, 360)"}},
      {"bad frame", doc("", R"({"generator": {}})", R"({"frame": "ecef", "keys": [{"t": 0, "position": [0,0,0]}]})"),
       {"path.frame", "local|geodetic"}},
      {"bad altitude", doc("", R"({"generator": {}})", R"({"altitude": "agl2", "keys": [{"t": 0, "position": [0,0,0]}]})"),
       {"path.altitude", "msl|agl"}},
      {"both file and generator", doc("", R"({"file": "/x.tif", "generator": {}})"), {"terrain", "exactly one", "not both"}},
      {"neither file nor generator", doc("", R"({"spacing_m": 30})"), {"terrain", "exactly one"}},
      {"file options with generator", doc("", R"({"generator": {}, "encoding": "png16"})"), {"terrain.encoding", "terrain.file"}},
      {"bad encoding", doc("", R"({"file": "/x.png", "encoding": "jpeg"})"), {"terrain.encoding", "auto|terrain-rgb|png16"}},
      {"zero scale", doc("", R"({"file": "/x.png", "scale": 0})"), {"terrain.scale", "0"}},
      {"unset env var", doc("", R"({"file": "${NOPE_UNSET_VAR}/x.tif"})"),
       {"terrain.file: environment variable NOPE_UNSET_VAR is not set"}},
      {"unset env var in imagery", doc(R"("render": {"imagery": "$NOPE_UNSET_VAR/o.png"})"),
       {"render.imagery: environment variable NOPE_UNSET_VAR is not set"}},
      {"generator size 1000", doc("", R"({"generator": {"size": 1000}})"), {"terrain.generator.size", "2^n+1", "1000"}},
      {"generator size 1", doc("", R"({"generator": {"size": 1}})"), {"terrain.generator.size", "2^n+1"}},
      {"generator size 32769", doc("", R"({"generator": {"size": 32769}})"), {"terrain.generator.size", "[3, 16385]"}},
      {"generator size huge", doc("", R"({"generator": {"size": 1e30}})"), {"terrain.generator.size", "2^n+1"}},
      {"generator size string", doc("", R"({"generator": {"size": "1025"}})"), {"terrain.generator.size", "2^n+1", "string"}},
      {"negative seed", doc("", R"({"generator": {"seed": -1}})"), {"terrain.generator.seed", "0..4294967295"}},
      {"ridge weight", doc("", R"({"generator": {"ridge_weight": 1.5}})"), {"terrain.generator.ridge_weight", "[0, 1]"}},
      {"step 0", doc(R"("time": {"step_s": 0})"), {"time.step_s", "(0, 1]"}},
      {"step 2", doc(R"("time": {"step_s": 2})"), {"time.step_s", "(0, 1]"}},
      {"negative duration", doc(R"("time": {"duration_s": -1})"), {"time.duration_s"}},
      {"too many frames", doc(R"("time": {"step_s": 1e-6, "duration_s": 1e6})"), {"time", "frames"}},
      {"capture after end", doc(R"("capture": {"times_s": [0, 5]})"), {"capture.times_s[1]", "[0, 4]"}},
      {"capture negative", doc(R"("time": {"duration_s": 10}, "capture": {"times_s": [-1]})"), {"capture.times_s[0]"}},
      {"capture every 0", doc(R"("capture": {"every_s": 0})"), {"capture.every_s", "> 0"}},
      {"capture every negative", doc(R"("capture": {"every_s": -2})"), {"capture.every_s", "> 0", "-2"}},
      {"capture every string", doc(R"("capture": {"every_s": "1s"})"), {"capture.every_s", "number", "string"}},
      {"capture every below the step", doc(R"("time": {"step_s": 0.1}, "capture": {"every_s": 0.05})"),
       {"capture.every_s", ">= time.step_s (0.1)", "0.05"}},
      {"capture key", doc(R"("capture": {"every": 1})"), {"capture.every: unknown key", "every_s"}},
      {"no channels", doc(R"("channels": [])"), {"channels", "at least one"}},
      {"latency mode", doc(R"("live": {"latency": "fast"})"), {"live.latency", "smooth", "fast"}},
      {"live key", doc(R"("live": {"delay": 1})"), {"live", "delay"}},
      {"duplicate channel names", doc(R"("channels": [{"name": "a"}, {"name": "a"}])"), {"channels[1].name", "duplicate"}},
      {"missing terrain", R"({"path": {"keys": [{"t": 0, "position": [0,0,0]}]}})", {"terrain", "missing"}},
      {"missing path", R"({"terrain": {"generator": {}}})", {"path", "missing"}},
      {"top level not object", "[1, 2]", {"object"}},
      {"render not object", doc(R"("render": 3)"), {"render", "object"}},
      {"duplicate key", doc(R"("render": {"width": 10, "width": 20})"), {"render.width", "duplicate"}},
      {"huge number", doc(R"("render": {"far_m": 1e400})"), {"<string>", "1e400"}},
      {"large value", doc(R"("render": {"far_m": 1e300})"), {"render.far_m"}},
      {"name with slash", doc(R"("name": "a/b")"), {"name", "'/'"}},
  };
  for (const ErrorCase& c : cases) {
    SCOPED_TRACE(c.label);
    const std::string msg = scenario_error_of(c.text);
    EXPECT_EQ(msg.rfind("<string>: ", 0), 0u) << msg;  // origin first
    for (const std::string& want : c.expect) {
      EXPECT_NE(msg.find(want), std::string::npos) << "message: " << msg << "\nwanted: " << want;
    }
  }
}

TEST(Scenario, SyntaxErrorReportsPosition) {
  const std::string text = "{\n  \"terrain\": {\"generator\": {}},\n  \"path\": {\"keys\": [}\n}\n";
  const std::string msg = scenario_error_of(text);
  EXPECT_NE(msg.find("line 3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("column"), std::string::npos) << msg;
  EXPECT_NE(msg.find("byte"), std::string::npos) << msg;
  EXPECT_NE(scenario_error_of("").find("line 1"), std::string::npos);
  EXPECT_NE(scenario_error_of("{\"a\": 1,}").find("invalid JSON"), std::string::npos);
}

TEST(Scenario, OriginPrefixesMessages) {
  try {
    parse_scenario(doc(R"("render": {"fov_deg": 60})"), "flights/x.json");
    FAIL() << "no error";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("flights/x.json: render.fov_deg: unknown key", 0), 0u) << e.what();
  }
}

TEST(Scenario, ExpandEnv) {
  ::setenv("IG_SCN_TEST_A", "/srv/dem", 1);
  ::setenv("IG_SCN_TEST_EMPTY", "", 1);
  EXPECT_EQ(expand_env("${IG_SCN_TEST_A}/x.tif"), "/srv/dem/x.tif");
  EXPECT_EQ(expand_env("$IG_SCN_TEST_A/x.tif"), "/srv/dem/x.tif");
  EXPECT_EQ(expand_env("a${IG_SCN_TEST_A}b$IG_SCN_TEST_A"), "a/srv/demb/srv/dem");
  // Set but empty: named, never silently "" ("${IG_DEM_DIR}/x.tif" would become "/x.tif").
  try {
    expand_env("${IG_SCN_TEST_EMPTY}/x.tif");
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_STREQ(e.what(), "environment variable IG_SCN_TEST_EMPTY is set but empty (in \"${IG_SCN_TEST_EMPTY}/x.tif\")");
  }
  EXPECT_EQ(expand_env("no vars"), "no vars");
  EXPECT_EQ(expand_env("cost $5 and $"), "cost $5 and $");  // a '$' not starting a name stays
  EXPECT_THROW(expand_env("${IG_SCN_TEST_A"), ScenarioError);
  EXPECT_THROW(expand_env("${}"), ScenarioError);
  EXPECT_THROW(expand_env("${1ABC}"), ScenarioError);
  try {
    expand_env("${NOPE_UNSET_VAR}/x");
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_STREQ(e.what(), "environment variable NOPE_UNSET_VAR is not set");
  }

  const Scenario s = parse_scenario(doc(R"("render": {"imagery": "${IG_SCN_TEST_A}/ortho.png"})",
                                        R"({"file": "${IG_SCN_TEST_A}/sierra.tif"})"));
  EXPECT_EQ(*s.terrain.file, "/srv/dem/sierra.tif");
  EXPECT_EQ(*s.render.imagery, "/srv/dem/ortho.png");
}

TEST(Scenario, LoadResolvesRelativePathsAgainstTheFile) {
  TempDir dir;
  ::setenv("IG_SCN_TEST_SUB", "dems", 1);
  const fs::path file = dir.write("flights/low_level.json",
                                  doc(R"("render": {"imagery": "../img/ortho.png"})",
                                      R"({"file": "${IG_SCN_TEST_SUB}/valley.tif"})"));
  const Scenario s = load_scenario(file.string());
  EXPECT_EQ(s.name, "low_level");  // the file's stem
  EXPECT_EQ(s.source_path, file.string());
  const fs::path base = fs::absolute(dir.path());
  EXPECT_EQ(*s.terrain.file, (base / "flights/dems/valley.tif").lexically_normal().string());
  EXPECT_EQ(*s.render.imagery, (base / "img/ortho.png").lexically_normal().string());

  // Absolute paths stay as they are; an explicit name wins over the stem.
  const fs::path abs = dir.write("abs.json", doc(R"("name": "named")", R"({"file": "/data/x.tif"})"));
  const Scenario a = load_scenario(abs.string());
  EXPECT_EQ(*a.terrain.file, "/data/x.tif");
  EXPECT_EQ(a.name, "named");

  // parse_scenario has no file: relative paths are left alone.
  EXPECT_EQ(*parse_scenario(doc("", R"({"file": "rel/x.tif"})")).terrain.file, "rel/x.tif");
}

TEST(Scenario, LoadErrorsNameTheFile) {
  TempDir dir;
  const fs::path missing = dir.path() / "missing.json";
  try {
    load_scenario(missing.string());
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
  const fs::path bad = dir.write("bad.json", doc(R"("render": {"width": -3})"));
  try {
    load_scenario(bad.string());
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(bad.string() + ": render.width", 0), 0u) << e.what();
  }
}

TEST(Scenario, ShippedScenariosParse) {
  const fs::path dir = fs::path(IG_SOURCE_DIR) / "scenarios";
  if (!fs::is_directory(dir)) GTEST_SKIP() << "no " << dir;
  if (std::getenv("IG_DEM_DIR") == nullptr) ::setenv("IG_DEM_DIR", "/nonexistent/ig_dem_dir", 1);
  int parsed = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    try {
      const Scenario s = load_scenario(entry.path().string());
      EXPECT_FALSE(s.name.empty());
      EXPECT_FALSE(s.channels.empty());
      EXPECT_FALSE(s.path.keys.empty());
      EXPECT_GE(scenario_frame_count(s), 1);
      ++parsed;
    } catch (const ScenarioError& e) {
      ADD_FAILURE() << e.what();
    }
  }
  if (parsed == 0) GTEST_SKIP() << "no scenario files in " << dir;
}

}  // namespace

// A key that is not a plain name is quoted in the message: a trailing space shows.
TEST(Scenario, AKeyWithASpaceIsQuoted) {
  const std::string e = scenario_error_of(
      doc("", R"({"generator": {"size": 257}})", R"({"keys": [{"t": 0, "position": [0, 0, 100], "hpr ": [0, 0, 0]}]})"));
  EXPECT_NE(e.find("path.keys[0].\"hpr \": unknown key"), std::string::npos) << e;
}
