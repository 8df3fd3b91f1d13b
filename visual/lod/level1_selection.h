#pragma once
// The two-level method's per-frame Level1 selection, without GL (drawing:
// render/twolevel_method.cpp): the eye guard that makes Level1 cover the
// ground under a low eye, the transition band's width, and which of the
// square's blocks to draw, nearest first. The size decision itself is
// lod/level1_size_controller.h, E is lod/look_at_point.h.

#include <functional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "lod/horizon_culling.h"
#include "terrain/height_pyramid.h"
#include "terrain/heightfield.h"

namespace ig::lod {

// Where Level1 goes this frame: N samples a side around the centre sample.
struct Level1Placement {
  int n = 0;
  glm::ivec2 centre{0};
  bool eye_guarded = false;  // the guard raised N or moved the centre
};

// Eye guard (docs/twolevel.md, our addition to the paper): while the eye is
// lower than kEyeGuardHeightFactor x Level0's maximum error above the DEM,
// Level1 grows to the smallest ladder size whose square around the centre
// also holds the eye with kEyeGuardMarginSamples to spare; when even the
// largest cannot, the square's centre moves from E towards the eye so the
// square starts that margin behind the eye. An eye outside the DEM or high
// enough leaves the placement as it is.
constexpr double kEyeGuardHeightFactor = 10.0;
constexpr int kEyeGuardMarginSamples = 32;
// eye_grid: the eye in sample units (x / spacing_x, y / spacing_y);
// eye_agl_m: its height above the DEM surface there.
Level1Placement guard_level1_for_eye(Level1Placement placement, glm::dvec2 eye_grid, double eye_agl_m,
                                     double level0_max_error_m, const std::vector<int>& ladder,
                                     glm::ivec2 dem_size);

// Band width w_trans = (r0 / r1) * alpha * w1 (r1 = 1: Level1 is full
// resolution; w1 = n - 1), rounded to the band stride, at least one stride,
// at most w1 / 4.
int band_width_samples(double level0_resolution, double alpha, int n, int stride);

// Min/max height over cells [i0, i1) x [j0, j1) from a pyramid level whose
// nodes are at least as large as the rectangle (a few nodes, conservative).
terrain::HeightPyramid::MinMax rect_minmax(const terrain::HeightPyramid& p, int i0, int j0, int i1, int j1);

// Level1 is drawn as blocks of this many quads a side.
constexpr int kLevel1BlockQuads = 32;
using BoxVisible = std::function<bool(const glm::dvec3& lo, const glm::dvec3& hi)>;
// Origins (lower-left samples) of the square's blocks whose boxes (the
// cells' min/max heights, the bottom lowered by below_m so a nearby coarser
// Level0 dip stays inside) pass `visible` (boxes in terrain-local metres),
// sorted nearest block centre first from eye_grid, so the depth test
// rejects hidden Level1 fragments before they are shaded. Blocks that
// `mark_hidden` (optional) marks as behind nearer terrain are left out too.
std::vector<glm::ivec2> visible_level1_blocks(const terrain::Heightfield& hf, const terrain::HeightPyramid& p,
                                              glm::ivec2 origin, int n, double below_m, const BoxVisible& visible,
                                              glm::dvec2 eye_grid, const MarkHidden& mark_hidden = {});

}  // namespace ig::lod
