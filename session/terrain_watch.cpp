#include "session/terrain_watch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "session/scenario_runner.h"
#include "terrain/georef.h"

namespace ig::session {
namespace {

// The frustum against node (level, i, j)'s box and, while it meets it, its
// children down to level 2 (4 cells a side: coarser boxes around the eye
// straddle every plane through it; levels 0 and 1 of a paged pyramid read
// tiles). Only nodes the frustum meets are opened, and the first one found
// ends the search.
bool node_in_view(const terrain::HeightPyramid& p, const terrain::Heightfield& hf, const render::Frustum& frustum,
                  const glm::dvec3& eye, int level, int i, int j) {
  const int size = 1 << level;
  const int i0 = i * size, j0 = j * size;
  const int i1 = std::min(i0 + size, p.cells_x()), j1 = std::min(j0 + size, p.cells_y());
  const auto mm = p.node(level, i, j);
  const glm::dvec3 lo(i0 * hf.spacing_x_m, j0 * hf.spacing_y_m, mm.lo);
  const glm::dvec3 hi(i1 * hf.spacing_x_m, j1 * hf.spacing_y_m, mm.hi);
  if (!frustum.intersects_box(lo - eye, hi - eye)) return false;
  if (level <= 2) return true;
  for (int cj = 2 * j; cj <= 2 * j + 1 && cj < p.level_height(level - 1); ++cj)
    for (int ci = 2 * i; ci <= 2 * i + 1 && ci < p.level_width(level - 1); ++ci)
      if (node_in_view(p, hf, frustum, eye, level - 1, ci, cj)) return true;
  return false;
}

std::string metres(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f", v);
  return buf;
}

std::string fixed(double v, int decimals) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string distance(double m) { return m >= 10000.0 ? metres(m / 1000.0) + " km" : metres(m) + " m"; }

}  // namespace

double distance_outside_terrain(const terrain::Heightfield& hf, const glm::dvec2& xy) {
  const glm::dvec2 extent(hf.extent_x_m(), hf.extent_y_m());
  const glm::dvec2 out_by = glm::max(glm::max(-xy, xy - extent), glm::dvec2(0.0));
  return glm::length(out_by);
}

bool terrain_in_view(const terrain::Heightfield& hf, const terrain::HeightPyramid& pyramid,
                     const render::Camera& local_camera) {
  if (pyramid.empty()) return true;  // no cells to judge by: never claim an empty view
  return node_in_view(pyramid, hf, render::frustum_of(local_camera), local_camera.position, pyramid.num_levels() - 1,
                      0, 0);
}

std::optional<double> depth_below_terrain(const terrain::Heightfield& hf, const glm::dvec3& eye) {
  if (!std::isfinite(eye.x) || !std::isfinite(eye.y) || !std::isfinite(eye.z) || hf.width < 2 || hf.height < 2 ||
      !hf.has_samples() || distance_outside_terrain(hf, glm::dvec2(eye)) > 0.0)
    return std::nullopt;
  return hf.sample_surface(eye.x, eye.y) - eye.z;
}

TerrainWatch::TerrainWatch(std::string command, std::function<void(const std::string&)> warn)
    : command_(std::move(command)), warn_(std::move(warn)) {
  if (!warn_) warn_ = [](const std::string& line) { std::cerr << line << "\n"; };
}

void TerrainWatch::observe(ScenarioRunner& runner, const FrameResult& f) {
  const render::TerrainScene& scene = runner.scene();
  std::vector<render::Camera> cameras;
  for (const auto& ch : runner.channels()) cameras.push_back(scene.local_camera(ch.camera));
  observe(runner.heightfield(), scene.height_pyramid(), f.frame, f.sim_time_s, f.pose.position - scene.world_origin(),
          cameras);
}

void TerrainWatch::observe(const terrain::Heightfield& hf, const terrain::HeightPyramid& pyramid, int frame,
                           double sim_time_s, const glm::dvec3& eye, const std::vector<render::Camera>& cameras) {
  const double outside_m = distance_outside_terrain(hf, glm::dvec2(eye));
  const bool in_view = std::any_of(cameras.begin(), cameras.end(),
                                   [&](const render::Camera& c) { return terrain_in_view(hf, pyramid, c); });
  if (outside_m > kOffTerrainM || !in_view) {
    ++frames_outside_;
    if (!outside_warned_) {
      outside_warned_ = true;
      std::string why;
      if (outside_m > kOffTerrainM)
        why = "is " + distance(outside_m) + " outside the terrain (0.." + metres(hf.extent_x_m()) + " m east, 0.." +
              metres(hf.extent_y_m()) + " m north)" +
              (in_view ? ": the terrain is seen only from afar" : ": no terrain is in view, only sky is drawn") +
              "; check the path or the host's position, the terrain, or terrain.generator.origin";
      else
        why = "looks where there is no terrain (none in any channel's view): only sky is drawn; check the "
              "attitude (path hpr, channel offsets) and the position";
      warn_(command_ + ": warning: " + describe(hf, frame, sim_time_s, eye) + " " + why +
            " (counted in summary.json frames_outside_terrain)");
    }
  }
  if (const auto depth = depth_below_terrain(hf, eye); depth && *depth > 0.0) {
    ++frames_below_;
    if (!below_warned_) {
      below_warned_ = true;
      warn_(command_ + ": warning: " + describe(hf, frame, sim_time_s, eye) + " is " + fixed(*depth, 1) +
            " m below the terrain surface (ground " + fixed(*depth + eye.z, 1) +
            " m): the view is from inside the terrain; check the path's altitudes (path.altitude msl or agl) "
            "or the host's (counted in summary.json frames_below_terrain)");
    }
  }
}

std::string TerrainWatch::describe(const terrain::Heightfield& hf, int frame, double sim_time_s,
                                   const glm::dvec3& eye) const {
  std::string s = "frame " + std::to_string(frame) + " (t " + fixed(sim_time_s, 3) + " s): the eye at local x " +
                  metres(eye.x) + " m, y " + metres(eye.y) + " m, z " + metres(eye.z) + " m";
  if (const auto g = terrain::local_to_geodetic(hf, eye.x, eye.y))
    s += " (lat " + fixed(g->x, 5) + ", lon " + fixed(g->y, 5) + ")";
  return s;
}

}  // namespace ig::session
