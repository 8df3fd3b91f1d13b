// Benchmark: the paper's Table 1 (Level1 size settling at 100 m above ground,
// view pitch 15..90 deg below the horizon) and two-level vs reference frame
// time on the same views. Prints a markdown table; asserts nothing.
//
//   IG_DEM_DIR=../shared/data/dem build/bin/bench_twolevel [--fov DEG] [--size WxH]
//       [--lat DEG --lon DEG --heading DEG] [--settle N] [--frames N] [--reference-frames N]
//       [--stepping] [--no-eye-guard]
//
// R is the visible-pixel ratio the controller uses (Level1 pixels / terrain
// pixels of the finished frame, occlusion queries); R_area the paper's
// projected-area ratio: the summed screen area of Level1's triangles over
// that of both levels' drawn triangles, each clipped to the view, hidden and
// overlapping parts included (lod/projected_area.h; no Earth curvature). "settle" is the frames
// after the view change until the size stopped changing. --stepping: the paper's one-step rule instead of the
// predicted sizes; --no-eye-guard: the controller alone decides.
//
// Defaults: 1280x1024, FOV 15 deg (the paper's), a point in the Sierra
// Nevada DEM's interior (37.70 N, 118.70 W), heading 270 (west, into the range).
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "session/scenario_runner.h"
#include "lod/projected_area.h"
#include "render/twolevel_method.h"
#include "stats/frame_log.h"

namespace {

struct Row {
  double pitch;
  int size = 0, next_size = 0;
  double ratio = 0, area_ratio = 0, level0 = 0, level1 = 0, band = 0;
  int settle_frames = 0;
  long long triangles = 0;
  double twolevel_ms = 0, reference_ms = 0;
  long long reference_triangles = 0;
  std::string passes;
};

// The paper's projected-area ratio for the last frame: the screen areas of
// the two levels' triangles (Level1's grid, Level0's triangles outside the
// square), each clipped to the view, summed with hidden parts included.
double projected_area_ratio(ig::session::ScenarioRunner& runner, const ig::render::TwoLevelMethod& tl) {
  const auto& ch = runner.channels()[0];
  const auto camera = runner.scene().local_camera(ch.camera);
  const auto& hf = runner.heightfield();
  const glm::dmat4 vp(camera.view_projection());
  const int w = ch.target->width(), h = ch.target->height();
  auto sample = [&](int i, int j) {
    return glm::dvec3(i * hf.spacing_x_m, j * hf.spacing_y_m, hf.at_clamped(i, j)) - camera.position;
  };
  auto area = [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return ig::lod::projected_area_px(vp, {a, b, c}, w, h);
  };
  const glm::ivec2 o = tl.level1_origin();
  const int n = tl.level1_size() - 1;
  double level1 = 0.0, level0 = 0.0;
  for (int j = o.y; j < o.y + n; ++j)
    for (int i = o.x; i < o.x + n; ++i)
      level1 += area(sample(i, j), sample(i + 1, j), sample(i + 1, j + 1)) +
                area(sample(i, j), sample(i + 1, j + 1), sample(i, j + 1));
  // Level0 as drawn: each triangle minus its part inside the square (the
  // triangle clipped by the square's four vertical planes, on its own plane).
  const glm::dvec3 lo = sample(o.x, o.y), hi = sample(o.x + n, o.y + n);
  const std::array<glm::dvec4, 4> sides = {glm::dvec4(1, 0, 0, -lo.x), glm::dvec4(-1, 0, 0, hi.x),
                                          glm::dvec4(0, 1, 0, -lo.y), glm::dvec4(0, -1, 0, hi.y)};
  const auto& m = tl.level0();
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    std::vector<glm::dvec3> tri;
    for (int k = 0; k < 3; ++k) tri.push_back(sample(m.samples[m.indices[t + k]].x, m.samples[m.indices[t + k]].y));
    std::vector<glm::dvec3> inside = tri;
    for (const auto& plane : sides) {
      std::vector<glm::dvec3> next;
      for (size_t k = 0; k < inside.size(); ++k) {
        const glm::dvec3 &a = inside[k], &b = inside[(k + 1) % inside.size()];
        const double da = glm::dot(glm::dvec3(plane), a) + plane.w, db = glm::dot(glm::dvec3(plane), b) + plane.w;
        if (da >= 0) next.push_back(a);
        if ((da >= 0) != (db >= 0)) next.push_back(a + (b - a) * (da / (da - db)));
      }
      inside = next;
    }
    level0 += area(tri[0], tri[1], tri[2]);
    if (inside.size() >= 3) level0 -= ig::lod::projected_area_px(vp, inside, w, h);
  }
  return level1 + level0 > 0 ? level1 / (level1 + level0) : 0.0;
}

double arg_double(int argc, char** argv, const std::string& flag, double fallback) {
  for (int k = 1; k + 1 < argc; ++k)
    if (flag == argv[k]) return std::atof(argv[k + 1]);
  return fallback;
}

}  // namespace

int main(int argc, char** argv) {
  const char* dem_dir = std::getenv("IG_DEM_DIR");
  if (!dem_dir) {
    std::fprintf(stderr, "bench_twolevel: set IG_DEM_DIR to the folder holding sierra_nevada_3arcsec_4097.tif\n");
    return 2;
  }
  const double fov = arg_double(argc, argv, "--fov", 15.0);
  const double lat = arg_double(argc, argv, "--lat", 37.70), lon = arg_double(argc, argv, "--lon", -118.70);
  const double heading = arg_double(argc, argv, "--heading", 270.0);
  const int settle = int(arg_double(argc, argv, "--settle", 30));
  const int frames = int(arg_double(argc, argv, "--frames", 20));
  const int ref_frames = int(arg_double(argc, argv, "--reference-frames", 3));
  bool stepping = false, no_guard = false;
  for (int k = 1; k < argc; ++k) {
    stepping = stepping || std::string(argv[k]) == "--stepping";
    no_guard = no_guard || std::string(argv[k]) == "--no-eye-guard";
  }
  int width = 1280, height = 1024;
  for (int k = 1; k + 1 < argc; ++k)
    if (std::string(argv[k]) == "--size") std::sscanf(argv[k + 1], "%dx%d", &width, &height);

  const std::vector<double> pitches = {15, 30, 45, 60, 75, 90};
  ig::io::Scenario s;
  s.name = "table1";
  s.terrain.file = std::string(dem_dir) + "/sierra_nevada_3arcsec_4097.tif";
  s.render.width = width;
  s.render.height = height;
  s.render.fov_y_deg = fov;
  s.channels = {ig::io::ChannelSpec{}};
  s.path.frame = ig::io::PositionFrame::Geodetic;
  s.path.altitude = ig::io::AltitudeMode::AboveGround;
  for (size_t k = 0; k < pitches.size(); ++k)
    s.path.keys.push_back({double(k), {lat, lon, 100.0}, heading, -pitches[k], 0.0});
  s.time_step_s = 1.0;
  s.duration_s = double(pitches.size() - 1);
  s.render.twolevel.predict_size = !stepping;
  s.render.twolevel.eye_guard = !no_guard;

  std::vector<Row> rows(pitches.size());
  ig::session::RunOptions o;
  o.headless = true;
  try {
    {
      o.method = "twolevel";
      ig::session::ScenarioRunner runner(s, o);
      // The benchmark reads the two-level method's own state (Level0, the
      // Level1 square), so it builds the method itself with the runner's settings.
      auto& channel = runner.channels().front();
      channel.method.reset();  // its window set goes back to the scene first
      auto own = std::make_unique<ig::render::TwoLevelMethod>(runner.scene(), runner.shader_dir(),
                                                              runner.scenario().render.twolevel);
      ig::render::TwoLevelMethod* tl = own.get();
      channel.renderer->set_method(*own);
      channel.method = std::move(own);
      std::printf("renderer: %s | %s\n", runner.context().gl_renderer().c_str(), runner.context().gl_version().c_str());
      std::printf("dem: %s (%dx%d), Level0: %d triangles built in %.0f ms, max error %.0f m\n",
                  runner.heightfield().source.c_str(), runner.heightfield().width, runner.heightfield().height,
                  tl->level0().triangle_count, tl->level0().build_ms, tl->level0().max_error_m);
      for (size_t k = 0; k < pitches.size(); ++k) {
        Row& r = rows[k];
        int last_size = tl->level1_size();
        for (int f = 0; f < settle; ++f) {
          runner.render_frame(int(k));
          if (tl->level1_size() != last_size) r.settle_frames = f + 1;
          last_size = tl->level1_size();
        }
        std::vector<double> ms;
        r.pitch = pitches[k];
        double ratio_sum = 0;
        for (int f = 0; f < frames; ++f) {
          runner.render_frame(int(k));
          const auto& ch = runner.channels()[0];
          ms.push_back(ch.render_ms);
          ratio_sum += tl->last_ratio();
          r.size = tl->level1_size();
          r.triangles = ch.last.method.triangles;
          r.passes = ch.last.method.passes;
          for (const auto& [name, v] : ch.last.method.columns) {
            if (name == "level0_tris") r.level0 = v;
            if (name == "level1_tris") r.level1 = v;
            if (name == "band_tris") r.band = v;
          }
        }
        r.ratio = ratio_sum / frames;
        r.area_ratio = projected_area_ratio(runner, *tl);
        r.twolevel_ms = ig::stats::percentiles(ms).median;
        runner.render_frame(int(k));
        r.next_size = tl->level1_size();
        std::fprintf(stderr, "twolevel pitch %.0f: N=%d R=%.2f %.1f ms\n", r.pitch, r.size, r.ratio, r.twolevel_ms);
      }
    }
    if (ref_frames > 0) {
      o.method = "reference";
      ig::session::ScenarioRunner runner(s, o);
      for (size_t k = 0; k < pitches.size(); ++k) {
        std::vector<double> ms;
        for (int f = 0; f < ref_frames; ++f) {
          runner.render_frame(int(k));
          ms.push_back(runner.channels()[0].render_ms);
        }
        rows[k].reference_ms = ig::stats::percentiles(ms).median;
        rows[k].reference_triangles = runner.channels()[0].last.method.triangles;
        std::fprintf(stderr, "reference pitch %.0f: %.1f ms\n", pitches[k], rows[k].reference_ms);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_twolevel: %s\n", e.what());
    return 1;
  }

  std::printf("\n%dx%d, FOV %.0f deg, 100 m above ground at %.2f, %.2f, heading %.0f; settle %d frames, median of %d; "
              "sizes %s, eye guard %s\n\n",
              width, height, fov, lat, lon, heading, settle, frames, stepping ? "stepped (paper)" : "predicted",
              no_guard ? "off" : "on");
  std::printf("| pitch below horizon | Level1 N | settle frames | R (visible) | R_area (projected) | triangles (L0 + L1 + band) | two-level ms (fps) | next N | reference ms | reference triangles | speed-up |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows)
    std::printf("| %.0f deg | %d | %d | %.0f %% | %.0f %% | %lld (%.0f + %.0f + %.0f) | %.1f (%.0f) | %d | %.1f | %lld | %.1fx |\n",
                r.pitch, r.size, r.settle_frames, 100.0 * r.ratio, 100.0 * r.area_ratio, r.triangles, r.level0,
                r.level1, r.band, r.twolevel_ms, 1000.0 / r.twolevel_ms, r.next_size, r.reference_ms,
                r.reference_triangles, r.reference_ms > 0 ? r.reference_ms / r.twolevel_ms : 0.0);
  return 0;
}
