#pragma once
// The two-level method's per-frame CPU step as a value (docs/twolevel.md):
// TwoLevelSelector holds what lives across frames (Level0's mesh and
// clusters, horizon culling, the Level1 size controller, last frame's
// square) and select() returns a TwoLevelSelection, everything the passes
// draw (visual/gl/twolevel_passes.h) and the scene requests of the frame.
// No GL: the rules here (far rule, eye guard, size control, paging hold) are
// unit-tested without a context.

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "lod/horizon_culling.h"
#include "lod/level0_clusters.h"
#include "lod/level0_height_query.h"
#include "lod/level1_size_controller.h"
#include "lod/look_at_point.h"
#include "lod/roam_level0_mesh.h"
#include "lod/scene_requests.h"
#include "options/twolevel_options.h"
#include "terrain/height_pyramid.h"
#include "terrain/heightfield.h"

namespace ig::lod {

// What the selection needs of the camera, in terrain-local metres (the
// renderer's Camera and Frustum live above this layer, so they come in as
// plain values and functions).
struct TwoLevelView {
  glm::dvec3 position{0.0}, forward{0.0, 1.0, 0.0}, up{0.0, 0.0, 1.0};
  double earth_radius_m = 0.0;
  double near_m = 0.5, far_m = 300000.0;
  glm::ivec2 viewport{640, 480};
  double pixels_per_radian = 0.0;  // at the viewport's centre
  // An eye-relative flat-terrain box may be in view (conservative).
  std::function<bool(const glm::dvec3& lo, const glm::dvec3& hi)> box_in_view;
  // World direction through pixel centre (px, py), py = 0 at the top row.
  std::function<glm::dvec3(double px, double py)> pixel_ray;
  // The pixel rectangle (x0, y0, x1, y1) holding an eye-relative box.
  std::function<glm::ivec4(const glm::dvec3& lo, const glm::dvec3& hi)> screen_rect;
};

// Paged heights, live (no_wait): the selection must not wait for tiles,
// and a new square is taken only when ready() says the heights it needs
// (samples [lo, hi] and the height window centred on window_centre) are all
// resident; asking may queue them.
struct Level1Paging {
  bool no_wait = false;
  std::function<bool(glm::ivec2 lo, glm::ivec2 hi, glm::ivec2 window_centre)> ready;
};

struct TwoLevelSelection {
  LookAtPoint look_at;
  glm::ivec2 origin{0};  // Level1's lower-left sample
  int n = 0;             // Level1 vertices a side (0 before the first frame)
  int band_w = 0;        // band width in samples
  bool eye_guarded = false;  // N or the centre came from the eye guard
  bool held = false;         // last frame's square kept: the new one's paged heights are not resident
  bool far = false;          // the far rule gave Level1 its smallest size
  double last_ratio = -1.0;  // the last measured coverage ratio R
  bool terrain_visible = false, band_visible = false;
  glm::ivec4 band_rect{0};  // the band's screen rectangle (x0, y0, x1, y1)
  std::vector<glm::ivec2> visible_blocks;  // Level1 block origins, nearest first
  // Level0 runs: [0] wholly outside the Level1 square, [1] across its edge,
  // [2] outside and out of the band's reach (lod/band_ring.h; empty unless
  // the band is shaded inline).
  std::array<IndexRuns, 3> level0_runs;
  int level0_hidden_clusters = 0, level1_hidden_blocks = 0;
  // Per wall vertex along level1_perimeter(n), top and bottom: (1, height);
  // filled when blocks are visible, for the stretches of the edge in view
  // (elsewhere a wall of no height at the lowest terrain). wall_version
  // changes whenever wall_z does (the passes upload it only then).
  std::vector<glm::vec2> wall_z;
  std::uint64_t wall_version = 0;
  SceneRequests scene_requests;  // window_set left -1: the method owns its windows
};

// Level1's edge samples relative to its origin, once around (the walls' order).
std::vector<glm::ivec2> level1_perimeter(int n);

class TwoLevelSelector {
 public:
  // Level0's error under this many pixels at the nearest point the largest
  // Level1 square around E could reach: Level1 takes its smallest size.
  static constexpr double kFarLevel0ErrorPx = 0.5;

  // level0: the static mesh (already lifted, z-ordered); hf and pyramid
  // outlive the selector. options.level0_budget must be resolved (> 0).
  TwoLevelSelector(const terrain::Heightfield& hf, const terrain::HeightPyramid& pyramid, Level0Mesh level0,
                   const options::TwoLevelOptions& options);

  // ratio: last frame's measured coverage ratio, < 0 when none came back.
  const TwoLevelSelection& select(const TwoLevelView& view, double ratio, const Level1Paging& paging = {});
  const TwoLevelSelection& last() const { return sel_; }

  int level1_size() const { return sel_.n > 0 ? sel_.n : controller_.size(); }
  const Level0Mesh& level0() const { return level0_; }
  const Level0HeightQuery& level0_heights() const { return level0_heights_; }
  double level0_resolution() const { return level0_resolution_; }  // Level0 vertices / DEM samples
  void set_thresholds(double a1, double a2) { controller_.set_thresholds(a1, a2); }
  // For tests: every Level0 cluster outside the square in runs[0], as if
  // the band could reach them all (on by default).
  void set_band_split(bool on) { band_split_ = on; }
  const Level1SizeController& controller() const { return controller_; }

 private:
  // Places Level1 (look-at point, far rule, size, eye guard); false when it
  // keeps last frame's square, paged heights it needs not being resident.
  bool place_level1(const TwoLevelView& view, double ratio, const glm::dvec2& eye, const Level1Paging& paging);
  void cull(const TwoLevelView& view, const glm::dvec2& eye, const Level1Paging& paging);

  const terrain::Heightfield& hf_;
  const terrain::HeightPyramid& pyramid_;
  options::TwoLevelOptions options_;
  Level0Mesh level0_;
  Level0HeightQuery level0_heights_;
  std::unique_ptr<Level0Clusters> clusters_;
  std::unique_ptr<HorizonCulling> horizon_;  // null when horizon culling is off
  Level1SizeController controller_;
  double level0_resolution_ = 0.0;
  bool band_split_ = true;
  std::vector<glm::dvec3> prediction_rays_;
  // Fills sel_.wall_z for the edge stretches (one block side each) that
  // may be in view and are not filled yet for this square.
  void update_walls(const TwoLevelView& view);
  // The square sel_.wall_z (and perimeter_, of walls_n_) was made for: the
  // walls' heights depend on nothing else (the DEM and Level0 do not
  // change), and the square moves by whole samples, not every frame.
  std::vector<glm::ivec2> perimeter_;
  glm::ivec2 walls_origin_{0};
  int walls_n_ = 0;
  std::vector<std::uint8_t> stretch_filled_;  // per block side along the perimeter
  double terrain_z_lo_ = 0.0, terrain_z_hi_ = 0.0;  // Level0's and the DEM's heights, lowest and highest
  TwoLevelSelection sel_;
};

}  // namespace ig::lod
