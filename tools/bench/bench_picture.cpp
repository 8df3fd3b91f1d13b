// Benchmark: what the picture features cost, side by side in one run.
// For each scenario and size, the same frames are drawn six ways in turn,
// frame by frame (plain, ground detail, FXAA-style post filter, 4x
// multisampling, and detail with each), by one method instance linked with
// the plain shading and one with the detail, and the medians are compared
// with the plain frame's.
// Prints a markdown table; asserts nothing.
//
//   IG_DEM_DIR=../shared/data/dem build/bin/bench_picture [--frames N] [--sizes 640x512,1280x1024]
//       [SCENARIO.json ...]     (default, from the project root: scenarios/default.json and
//                                 scenarios/table2_sierra.json)
//
// Per variant: median wall ms of the view (LOD update + passes + resolve,
// glFinish at each stage), median CPU ms of the process over the same span
// (llvmpipe's rasterizer threads included), fragment and vertex shader
// invocations (pipeline statistics, hardware-independent), fragments per
// pixel, and the wall-time ratio to the plain frame.
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "gl/render_target.h"
#include "render/frame_renderer.h"
#include "render/terrain_method.h"
#include "session/scenario_runner.h"
#include "session/view_step.h"
#include "stats/timing.h"

namespace {

using Clock = ig::stats::WallClock;

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Variant {
  const char* name;
  bool detail;
  std::unique_ptr<ig::gl::RenderTarget> target;
  std::vector<double> wall, cpu, fs, vs;
};

void run(const std::string& file, int w, int h, int frames) {
  ig::io::Scenario s = ig::io::load_scenario(file);
  s.channels.resize(1);
  s.render.shading.ground_detail = true;
  ig::session::RunOptions o;
  o.width = w;
  o.height = h;
  o.headless = true;
  ig::session::ScenarioRunner runner(std::move(s), o);
  auto& ch = runner.channels().front();
  // One method and renderer per shading (ground detail or plain; deferred
  // for single-sampled targets, in the terrain pass for multisampled ones),
  // each made under its scene settings; all draw with the same scene and cameras.
  auto& scene = runner.scene();
  struct Shading {
    std::unique_ptr<ig::render::TerrainMethod> method;
    std::unique_ptr<ig::render::FrameRenderer> renderer;
  };
  std::map<std::pair<bool, bool>, Shading> shadings;  // (detail, deferred)
  const bool deferred_default = scene.deferred_shading();
  for (bool detail : {false, true})
    for (bool deferred : {false, true}) {
      scene.set_ground_detail(detail);
      scene.set_deferred_shading(deferred);
      Shading& sh = shadings[{detail, deferred}];
      sh.method = ig::render::make_method(runner.scenario().render.method, scene, runner.shader_dir(),
                                          runner.scenario().render.method_options());
      sh.renderer = std::make_unique<ig::render::FrameRenderer>(scene, *sh.method, runner.shader_dir());
    }
  scene.set_ground_detail(true);
  scene.set_deferred_shading(deferred_default);
  std::vector<Variant> variants;
  for (const auto& [name, detail, aa] : {std::tuple{"plain", false, "off"}, std::tuple{"detail", true, "off"},
                                         std::tuple{"fxaa", false, "fxaa"}, std::tuple{"msaa 4x", false, "msaa"},
                                         std::tuple{"detail + fxaa", true, "fxaa"},
                                         std::tuple{"detail + msaa 4x", true, "msaa"}}) {
    ig::io::RenderSpec r = runner.scenario().render;
    r.antialiasing = aa;
    r.msaa_samples = 4;
    variants.push_back({name, detail, ig::session::make_frame_target(r, w, h), {}, {}, {}, {}});
  }
  const int total = runner.frame_count();
  frames = std::max(1, std::min(frames, total));
  for (int i = 0; i < frames; ++i) {
    const int k = frames == 1 ? 0 : int((long long)i * (total - 1) / (frames - 1));
    const ig::io::Pose pose = runner.pose_at(k * runner.scenario().time_step_s);
    const ig::render::Camera camera = runner.camera_for(pose, ch);
    for (std::size_t r = 0; r < variants.size(); ++r) {
      Variant& v = variants[(r + i) % variants.size()];  // rotated, so no variant always goes first
      ig::render::FrameRenderer& renderer = *shadings.at({v.detail, v.target->samples() == 1}).renderer;
      const double c0 = ig::stats::process_cpu_ms();
      const auto t0 = Clock::now();
      const auto result = ig::session::render_view(scene, renderer, camera, *v.target);
      v.wall.push_back(ig::stats::ms_since(t0));
      v.cpu.push_back(ig::stats::process_cpu_ms() - c0);
      v.fs.push_back(double(result.total.fs_invocations));
      v.vs.push_back(double(result.total.vs_invocations));
    }
  }
  std::printf("\n### %s, %dx%d, %s, %d frames (samples: %d max)\n\n", runner.scenario().name.c_str(), w, h,
              runner.scenario().render.method.c_str(), frames, ig::gl::max_samples());
  std::printf("| variant | wall ms (median) | CPU ms (median) | fragments (M) | fragments / pixel | vertices (k) | wall ratio | CPU ratio |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  const double base_wall = median(variants[0].wall), base_cpu = median(variants[0].cpu);
  for (const Variant& v : variants) {
    const double fs = median(v.fs);
    std::printf("| %s | %.2f | %.2f | %.3f | %.2f | %.1f | %.2f | %.2f |\n", v.name, median(v.wall), median(v.cpu),
                fs / 1e6, fs / (double(w) * h), median(v.vs) / 1e3, median(v.wall) / base_wall,
                median(v.cpu) / base_cpu);
  }
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  int frames = 24;
  std::vector<std::pair<int, int>> sizes = {{640, 512}, {1280, 1024}};
  std::vector<std::string> files;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--frames" && k + 1 < argc) {
      frames = std::max(1, std::atoi(argv[++k]));
    } else if (a == "--sizes" && k + 1 < argc) {
      sizes.clear();
      std::string list = argv[++k];
      for (std::size_t p = 0; p <= list.size();) {
        const std::size_t q = std::min(list.find(',', p), list.size());
        int w = 0, h = 0;
        if (std::sscanf(list.substr(p, q - p).c_str(), "%dx%d", &w, &h) == 2 && w > 0 && h > 0) sizes.push_back({w, h});
        p = q + 1;
      }
    } else {
      files.push_back(a);
    }
  }
  if (files.empty()) {
    files.push_back("scenarios/default.json");  // run from the project's root
    if (std::getenv("IG_DEM_DIR")) files.push_back("scenarios/table2_sierra.json");
    else std::fprintf(stderr, "bench_picture: IG_DEM_DIR not set: the Table 2 flight is skipped\n");
  }
  try {
    for (const auto& f : files)
      for (const auto& [w, h] : sizes) run(f, w, h, frames);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_picture: %s\n", e.what());
    return 1;
  }
  return 0;
}
