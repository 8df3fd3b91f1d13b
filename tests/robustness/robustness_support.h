#pragma once
// Shared pieces of the robustness tests (tests/robustness/*_test.cpp): one
// headless GL context per test binary, small in-memory terrains, a rig that
// renders one method over one terrain through the FrameRenderer (the same
// path ig run takes), and checks that every pixel and log value is finite.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/gl_context.h"
#include "gl/render_target.h"
#include "io/pose.h"
#include "render/camera.h"
#include "render/frame_renderer.h"
#include "render/terrain_method.h"
#include "render/terrain_scene.h"
#include "render/twolevel_method.h"
#include "terrain/height_pyramid.h"
#include "terrain/heightfield.h"
#include "terrain/ray_cast.h"
#include "terrain/synthetic_terrain.h"
#include "session/view_step.h"

namespace robustness {

inline std::string shader_dir() { return std::string(IG_BIN_DIR) + "/shaders"; }

// One context for the whole binary, made current once and kept.
inline void ensure_gl() {
  static std::unique_ptr<ig::gl::GlContext> context = ig::gl::create_headless_context();
  (void)context;
}

// ------------------------------------------------------------- terrains --

inline ig::terrain::Heightfield grid(int w, int h, double spacing, const std::string& name) {
  ig::terrain::Heightfield hf;
  hf.width = w;
  hf.height = h;
  hf.spacing_x_m = hf.spacing_y_m = spacing;
  hf.heights.assign(size_t(w) * size_t(h), 0.0f);
  hf.source = name;
  return hf;
}

inline ig::terrain::Heightfield flat_terrain(int n, double spacing, float height_m) {
  auto hf = grid(n, n, spacing, "flat");
  std::fill(hf.heights.begin(), hf.heights.end(), height_m);
  hf.finalize_stats();
  return hf;
}

// Seeded fractal mountains (the generator the default scenario uses).
inline ig::terrain::Heightfield hills(int size = 257, double spacing = 30.0, double relief = 900.0) {
  ig::options::SyntheticTerrainOptions p;
  p.size = size;
  p.seed = 11;
  p.spacing_m = spacing;
  p.relief_m = relief;
  p.base_m = 100.0;
  p.octaves = 7;
  return ig::terrain::generate_synthetic_terrain(p);
}

// A temporary directory for files the tests write (ESRI ASCII grids).
inline std::filesystem::path temp_dir() {
  const auto dir = std::filesystem::temp_directory_path() / "ig_robustness_test";
  std::filesystem::create_directories(dir);
  return dir;
}

// ------------------------------------------------------------- cameras --

inline ig::render::Camera camera_at(glm::dvec3 position, double heading, double pitch, double roll = 0.0,
                                    double fov_y = 60.0, int w = 160, int h = 120) {
  ig::render::Camera c;
  c.position = position;
  c.attitude = ig::io::attitude_from_hpr({heading, pitch, roll});
  c.fov_y_deg = fov_y;
  c.aspect = double(w) / double(h);
  c.near_m = 0.1;
  c.far_m = 300000.0;
  return c;
}

// ---------------------------------------------------------------- frames --

struct Frame {
  int w = 0, h = 0;
  std::vector<float> depth;
  std::vector<std::uint8_t> rgba;
  ig::render::Camera camera;  // the world camera it was rendered with
  ig::render::ViewResult result;
  std::optional<double> error_bound_px;

  float d(int x, int y) const { return depth[size_t(y) * w + x]; }
  bool terrain(int x, int y) const { return d(x, y) > 0.0f; }
  const std::uint8_t* px(int x, int y) const { return &rgba[(size_t(y) * w + x) * 4]; }
  double view_distance(int x, int y) const { return camera.depth_to_view_distance(d(x, y)); }
  // World position seen at a terrain pixel (from its depth).
  glm::dvec3 world(int x, int y) const {
    const glm::dvec3 ray = camera.pixel_ray(x, y, w, h);
    return camera.position + ray * (view_distance(x, y) / glm::dot(ray, camera.forward()));
  }
  long long terrain_pixels() const {
    long long n = 0;
    for (float v : depth) n += v > 0.0f;
    return n;
  }
};

// Every depth finite and in [0, 1], no black pixel (a NaN colour ends up
// as 0 in RGBA8; terrain and sky are never that dark), every method log
// column and the error bound finite. Returns a description of the first
// problem, or "" when none.
inline std::string finite_problems(const Frame& f) {
  long long bad_depth = 0, black = 0;
  for (float v : f.depth) bad_depth += !(std::isfinite(v) && v >= 0.0f && v <= 1.0f);
  for (size_t p = 0; p < f.rgba.size(); p += 4) black += int(f.rgba[p]) + f.rgba[p + 1] + f.rgba[p + 2] < 12;
  std::string out;
  if (bad_depth) out += std::to_string(bad_depth) + " depth values non-finite or outside [0,1]; ";
  if (black) out += std::to_string(black) + " black (NaN) pixels; ";
  for (const auto& [name, value] : f.result.method.columns)
    if (!std::isfinite(value)) out += "column " + name + " = " + std::to_string(value) + "; ";
  if (f.error_bound_px && !(std::isfinite(*f.error_bound_px) && *f.error_bound_px >= 0.0))
    out += "error_bound_px = " + std::to_string(*f.error_bound_px) + "; ";
  for (double t : {f.result.timings.lod_ms, f.result.timings.terrain_ms, f.result.timings.sky_ms})
    if (!std::isfinite(t)) out += "timing non-finite; ";
  return out;
}

// One method over one terrain, its own render target; the heightfield is
// owned here so the scene's reference to it stays valid.
class Rig {
 public:
  // earth_radius_m is set on the scene before the method is made (as
  // ScenarioRunner does): methods that build meshes at construction see it.
  Rig(ig::terrain::Heightfield hf, const std::string& method, int w = 160, int h = 120,
      ig::render::ShadingParams shading = {}, ig::render::TwoLevelOptions twolevel = {},
      double earth_radius_m = 0.0)
      : hf_(std::make_unique<ig::terrain::Heightfield>(std::move(hf))) {
    ensure_gl();
    scene_ = std::make_unique<ig::render::TerrainScene>(*hf_, shading);
    scene_->set_earth_radius(earth_radius_m);
    method_ = ig::render::make_method(method, *scene_, shader_dir(), twolevel);
    renderer_ = std::make_unique<ig::render::FrameRenderer>(*scene_, *method_, shader_dir());
    target_ = std::make_unique<ig::gl::RenderTarget>(w, h);
  }
  ig::render::TerrainScene& scene() { return *scene_; }
  ig::render::TerrainMethod& method() { return *method_; }
  ig::render::FrameRenderer& renderer() { return *renderer_; }
  const ig::terrain::Heightfield& heightfield() const { return *hf_; }
  const ig::gl::RenderTarget& target() const { return *target_; }

  // Renders `frames` frames of the same camera (LOD state settles) and reads the last back.
  Frame render(const ig::render::Camera& camera, int frames = 1) {
    Frame f;
    for (int k = 0; k < frames; ++k) f.result = ig::session::render_view(*scene_, *renderer_, camera, *target_);
    f.w = target_->width();
    f.h = target_->height();
    f.depth = target_->read_depth();
    f.rgba = target_->read_rgba();
    f.camera = camera;
    f.error_bound_px = method_->error_bound_px(scene_->local_camera(camera), f.h);
    return f;
  }

 private:
  std::unique_ptr<ig::terrain::Heightfield> hf_;
  std::unique_ptr<ig::render::TerrainScene> scene_;
  std::unique_ptr<ig::render::TerrainMethod> method_;
  std::unique_ptr<ig::render::FrameRenderer> renderer_;
  std::unique_ptr<ig::gl::RenderTarget> target_;
};

inline ig::render::TwoLevelMethod* as_twolevel(ig::render::TerrainMethod& m) {
  return dynamic_cast<ig::render::TwoLevelMethod*>(&m);
}

}  // namespace robustness
