// What TerrainWatch (session/terrain_watch.h) costs a frame: ig run and
// ig serve judge every frame's pose and views with it after rendering.
//
//   bench_terrain_watch [DEM_FILE] [poses=2000]
//
// Without a DEM file, a generated 4097^2 terrain (30 m, 1500 m relief).
// Prints mean / median / p99 / max microseconds of one observe() (one
// channel, 60 deg x 4:3) for three kinds of pose, drawn with a fixed seed:
// (a) 100 m above the ground looking 5 deg down (terrain in view: the search
// stops at its first box), (b) the same eyes looking 60 deg up (sky only:
// every box near the frustum is opened), (c) 500 km outside the terrain.
// Single-threaded, no GL.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "io/pose.h"
#include "session/terrain_watch.h"
#include "terrain/dem_loader.h"
#include "terrain/earth_curvature.h"
#include "terrain/height_pyramid.h"
#include "terrain/synthetic_terrain.h"

namespace {

using Clock = std::chrono::steady_clock;

struct Pose {
  glm::dvec3 eye;
  double heading, pitch;
};

void report(const char* what, const ig::terrain::Heightfield& hf, const ig::terrain::HeightPyramid& pyramid,
            const std::vector<Pose>& poses, double earth_radius_m) {
  ig::session::TerrainWatch watch("bench", [](const std::string&) {});
  std::vector<double> us;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    ig::render::Camera c;
    c.position = poses[k].eye;
    c.attitude = ig::io::attitude_from_hpr(ig::io::Hpr{poses[k].heading, poses[k].pitch, 0.0});
    c.fov_y_deg = 60.0;
    c.aspect = 4.0 / 3.0;
    c.earth_radius_m = earth_radius_m;
    const auto t0 = Clock::now();
    watch.observe(hf, pyramid, int(k), 0.0, c.position, {c});
    us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
  }
  std::sort(us.begin(), us.end());
  double sum = 0.0;
  for (double v : us) sum += v;
  std::printf("%-34s mean %8.2f us  median %8.2f  p99 %8.2f  max %8.2f   (%llu of %zu counted outside)\n", what,
              sum / double(us.size()), us[us.size() / 2], us[std::min(us.size() - 1, us.size() * 99 / 100)],
              us.back(), static_cast<unsigned long long>(watch.frames_outside()), us.size());
}

}  // namespace

int main(int argc, char** argv) {
  const std::string file = argc > 1 ? argv[1] : "";
  const int n = argc > 2 ? std::atoi(argv[2]) : 2000;
  if (n <= 0) {
    std::fprintf(stderr, "usage: bench_terrain_watch [DEM_FILE] [poses=2000]\n");
    return 2;
  }
  ig::terrain::Heightfield hf;
  if (file.empty()) {
    ig::options::SyntheticTerrainOptions p;
    p.size = 4097;
    hf = ig::terrain::generate_synthetic_terrain(p);
  } else {
    hf = ig::terrain::load_dem(file, {});
  }
  const ig::terrain::HeightPyramid pyramid(hf);
  // Curvature as `ig run` draws a georeferenced DEM file over 5 km (earth_curvature auto).
  const double radius = !file.empty() && hf.georef ? ig::terrain::kEarthRadiusM : 0.0;
  std::printf("%s: %d x %d samples, %.0f x %.0f m, curvature %s\n", hf.source.c_str(), hf.width, hf.height,
              hf.extent_x_m(), hf.extent_y_m(), radius > 0 ? "on" : "off");

  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Pose> down, up, away;
  for (int k = 0; k < n; ++k) {
    const double x = u(rng) * hf.extent_x_m(), y = u(rng) * hf.extent_y_m(), heading = u(rng) * 360.0;
    const glm::dvec3 eye(x, y, hf.sample_surface(x, y) + 100.0);
    down.push_back({eye, heading, -5.0});
    up.push_back({eye, heading, 60.0});
    away.push_back({glm::dvec3(-500000.0, y, 1500.0), heading, -5.0});
  }
  report("(a) 100 m AGL, 5 deg down", hf, pyramid, down, radius);
  report("(b) 100 m AGL, 60 deg up (sky)", hf, pyramid, up, radius);
  report("(c) 500 km outside", hf, pyramid, away, radius);
  return 0;
}
