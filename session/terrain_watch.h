#pragma once
// Whether a frame showed the terrain at all. An empty picture is otherwise
// silent: a wrong longitude or origin draws sky only, an eye under the
// ground draws the terrain's underside. TerrainWatch counts, per frame,
//  * frames outside the terrain: the pose more than kOffTerrainM outside the
//    DEM's extent, or no part of the terrain in any channel's view frustum;
//  * frames below the terrain: the eye lower than the surface beneath it;
// and says so once for each, naming the first such pose. ig run and
// ig serve both use it (through RunOutputs), judged outside the LOD methods
// so every method is counted alike.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/camera.h"
#include "terrain/height_pyramid.h"
#include "terrain/heightfield.h"

namespace ig::session {

class ScenarioRunner;
struct FrameResult;

// A pose further than this outside the terrain's extent is off the terrain.
constexpr double kOffTerrainM = 1000.0;

// Horizontal distance (m) from local (x, y) to the terrain's extent; 0 inside.
double distance_outside_terrain(const terrain::Heightfield& hf, const glm::dvec2& xy);

// Whether any part of the terrain can be in the view of `local_camera`
// (terrain-local position, earth_radius_m set as the scene draws): the
// frustum against the min/max pyramid's boxes, descending to nodes of 4
// cells. Conservative: false only when no box is in view (sky only), so a
// true may still be a view of terrain hidden behind the near plane.
bool terrain_in_view(const terrain::Heightfield& hf, const terrain::HeightPyramid& pyramid,
                     const render::Camera& local_camera);

// Metres the local eye is below the terrain surface under it (> 0: below);
// nullopt when the eye is not over the terrain.
std::optional<double> depth_below_terrain(const terrain::Heightfield& hf, const glm::dvec3& local_eye);

class TerrainWatch {
 public:
  // `command` prefixes the warnings ("ig run"); `warn` receives each
  // warning line once (default: stderr).
  explicit TerrainWatch(std::string command, std::function<void(const std::string&)> warn = nullptr);

  // After runner rendered frame f: judges its pose and every channel's view.
  void observe(ScenarioRunner& runner, const FrameResult& f);
  // The same for one pose and view (tests, front ends without a runner):
  // local_eye and cameras in terrain-local metres.
  void observe(const terrain::Heightfield& hf, const terrain::HeightPyramid& pyramid, int frame, double sim_time_s,
               const glm::dvec3& local_eye, const std::vector<render::Camera>& local_cameras);

  std::uint64_t frames_outside() const { return frames_outside_; }
  std::uint64_t frames_below() const { return frames_below_; }

 private:
  std::string describe(const terrain::Heightfield& hf, int frame, double sim_time_s, const glm::dvec3& eye) const;

  std::string command_;
  std::function<void(const std::string&)> warn_;
  std::uint64_t frames_outside_ = 0, frames_below_ = 0;
  bool outside_warned_ = false, below_warned_ = false;
};

}  // namespace ig::session
