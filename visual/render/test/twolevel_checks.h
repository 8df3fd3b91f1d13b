#pragma once
// Shared by the two-level image tests (twolevel_test.cpp,
// twolevel_motion_test.cpp): scenarios with a replaced path, the runner's
// two-level method, frames grabbed to the CPU, dumps and recorded figures.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>

#include "render/test/frame_dump.h"
#include "render/test/target_pixels.h"
#include "capture/png_writer.h"
#include "session/scenario_runner.h"
#include "io/pose.h"
#include "io/scenario.h"
#include "lod/level1_size_controller.h"
#include "render/twolevel_method.h"
#include "stats/image_error.h"

namespace twolevel_checks {

using namespace ig::io;
using namespace ig::session;

inline ig::io::Scenario default_scenario() {
  return ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json");
}

inline RunOptions options(const std::string& method, int w, int h) {
  RunOptions o;
  o.width = w;
  o.height = h;
  o.method = method;
  o.headless = true;
  o.shader_dir = std::string(IG_BIN_DIR) + "/shaders";
  return o;
}

inline PathKey key(double t, double x, double y, double z, double heading, double pitch, double roll = 0.0) {
  return PathKey{t, {x, y, z}, heading, pitch, roll};
}

// The scenario with its path replaced: key k at t = k seconds, 1 s steps,
// so render_frame(k) shows key k exactly (and frames past the end the last key).
inline Scenario with_keys(Scenario s, std::vector<PathKey> keys, AltitudeMode altitude) {
  for (size_t k = 0; k < keys.size(); ++k) keys[k].t_s = double(k);
  s.path.frame = ig::io::PositionFrame::Local;
  s.path.altitude = altitude;
  s.path.keys = std::move(keys);
  s.time_step_s = 1.0;
  s.duration_s = double(s.path.keys.size() - 1);
  s.capture_times_s.clear();
  return s;
}

inline ig::render::TwoLevelMethod& twolevel(ScenarioRunner& r) {
  auto* m = dynamic_cast<ig::render::TwoLevelMethod*>(&r.method());
  if (!m) throw std::runtime_error("runner's method is not twolevel");
  return *m;
}

struct Frame : TargetPixels {
  ig::render::Camera camera;
  std::string passes;
  long long triangles = 0;
  float d(int x, int y) const { return depth[size_t(y) * w + x]; }
  std::uint8_t alpha(int x, int y) const { return rgba[(size_t(y) * w + x) * 4 + 3]; }
  double view_distance(int x, int y) const { return camera.depth_to_view_distance(d(x, y)); }
  // World position of the surface seen at pixel (x, y) (terrain pixels only).
  glm::dvec3 world(int x, int y) const {
    const glm::dvec3 ray = camera.pixel_ray(x, y, w, h);
    const double t = view_distance(x, y) / glm::dot(ray, camera.forward());
    return camera.position + ray * t;
  }
};

inline ig::stats::FrameImage image(const Frame& f) { return {f.w, f.h, f.rgba, f.depth}; }

inline Frame grab(ScenarioRunner& r) {
  auto& ch = r.channels().front();
  Frame f;
  f.read(*ch.target);
  f.camera = ch.camera;
  f.passes = ch.last.method.passes;
  f.triangles = ch.last.method.triangles;
  return f;
}

// With IG_TWOLEVEL_DUMP=<dir> set, frames are written there as PNG (alpha
// forced opaque) for a look.
inline void dump(const Frame& f, const std::string& name) { dump_frame("IG_TWOLEVEL_DUMP", f.rgba, f.w, f.h, name); }

inline void record(const std::string& name, double value) {
  ::testing::Test::RecordProperty(name, std::to_string(value));
}
}  // namespace twolevel_checks
