#pragma once
// View-dependent ROAM (Duchaineau et al. 1997) over a whole DEM, rebuilt
// from the patch roots every frame (see docs/baselines.md, "roam"):
//
//   - The DEM is covered by square bintree patches (roam_patch_grid.h), two
//     root triangles each, linked to their neighbours across patch edges.
//   - A triangle is split when its wedgie thickness e (roam_wedgie_grid.h)
//     seen from the eye exceeds tau pixels: e / D * pixels_per_radian > tau,
//     D = distance from the eye to the triangle's bounding box (its extent,
//     heights from its corners +- e). e and the box nest (a child's are
//     within its parent's), so the priority never grows down the tree.
//   - Every split is a diamond split: a triangle whose base neighbour is
//     coarser first forces that neighbour to split (recursively), so the
//     mesh has no T-junctions.
//   - Triangles whose box is outside the view volume are neither refined nor
//     drawn; nor is anything wholly outside the DEM. Triangles crossing the
//     DEM's east/north edge are clipped to it and count twice their e (the
//     clip points take the DEM's heights, which may sit e off the plane).
//
// Output: triangles as DEM sample indices (3 vertices each, counter-clockwise
// seen from above), drawn by shaders/level0.vert. No GL here.

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/gtc/type_precision.hpp>

#include "lod/roam_patch_grid.h"
#include "lod/roam_surface.h"
#include "lod/roam_wedgie_grid.h"
#include "terrain/heightfield.h"

namespace ig::lod {

struct RoamFrameStats {
  long long splits = 0;         // diamond splits this frame (each splits two triangles, one at a mesh edge)
  long long forced_splits = 0;  // of which forced by a finer neighbour
  long long nodes = 0;          // bintree triangles built (all levels)
  long long triangles = 0;      // triangles output (after clipping)
  long long culled = 0;         // leaves left out as outside the view
  // Largest error / distance (radians) over the output triangles: the
  // screen-space error bound is this times pixels per radian.
  double max_error_ratio = 0.0;
};

// One frame's mesh, as a value the renderer consumes.
struct RoamSelection {
  std::vector<glm::u16vec2> vertices;  // triangles as DEM sample indices, 3 per triangle
  RoamFrameStats stats;
};

class RoamTessellator {
 public:
  // Throws std::invalid_argument for grids smaller than 2 x 2 or wider or
  // taller than 65536 samples (vertices are 16-bit sample indices).
  // earth_radius_m > 0: the scene is drawn curved; the drop is applied per
  // vertex, so each triangle's error also counts its sag L^2 / (8 R) (L its
  // hypotenuse), else flat ground would never refine.
  explicit RoamTessellator(const terrain::Heightfield& hf, double earth_radius_m = 0.0);

  // Builds the mesh for an eye at `eye` (terrain-local metres). tau_px >= 0.
  // Distances below min_distance_m (the near plane) count as that, so the
  // bound stays finite with the eye inside a triangle's box. `recycled`
  // (last frame's selection) lends its memory.
  RoamSelection select(const glm::dvec3& eye, double tau_px, double pixels_per_radian, const BoxInView& in_view = {},
                       double min_distance_m = 0.5, RoamSelection recycled = {});

  const PatchGrid& grid() const { return grid_; }
  const RoamWedgieGrid& wedgies() const { return wedgies_; }
  double build_ms() const { return build_ms_; }

 private:
  // 32 bytes: the pool is rewritten every frame, so its size is memory traffic.
  struct Tri {
    glm::u16vec2 v[3];  // apex, left, right: counter-clockwise; the base (hypotenuse) runs left -> right
    int child = -1;     // first of two consecutive children: (mid, apex, left), (mid, right, apex)
    int base = -1, left = -1, right = -1;  // neighbours across the base, the left (apex-left), right (right-apex) edges
    float ratio = kUnknown;  // in view: error / distance (>= 0); else kUnknown or kCulled
  };
  static constexpr float kUnknown = -1.0f, kCulled = -2.0f;

  void refine(int id);
  void split(int id, bool forced);
  void evaluate(Tri& t) const;
  void emit(int id);
  float error_of(const Tri& t) const;

  const terrain::Heightfield& hf_;
  PatchGrid grid_;
  PaddedHeights heights_;
  RoamWedgieGrid wedgies_;
  double build_ms_ = 0.0;

  // Per frame (sel_ is handed out at the end of select).
  glm::dvec3 eye_{0.0};
  double threshold_ = 0.0;  // split when ratio > threshold_ (= tau / pixels per radian)
  double min_distance_ = 0.5;
  double earth_radius_m_ = 0.0;
  const BoxInView* in_view_ = nullptr;
  std::vector<Tri> tris_;
  RoamSelection sel_;
};

}  // namespace ig::lod
