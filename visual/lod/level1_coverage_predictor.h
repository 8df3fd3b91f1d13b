#pragma once
// Predicts, before drawing, the ratio R = Level1 pixels / terrain pixels for
// every size on the Level1 ladder, so the size controller settles
// within a frame or two rather than one size step per frame. A coarse
// grid of view rays is cast against the terrain (exact ray cast on the
// min/max pyramid); a ray that hits inside the N x N square Level1 would
// occupy around E counts for size N. The same visible-pixel ratio the GPU
// counts afterwards, on a few dozen rays. No GL.

#include <optional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "terrain/heightfield.h"
#include "terrain/height_pyramid.h"

namespace ig::lod {

struct CoveragePrediction {
  std::vector<double> ratio;  // per ladder size; empty when no ray hit the terrain
  int rays = 0, terrain_hits = 0;
  std::vector<glm::dvec3> hits;  // where the rays met the terrain (paged heights prefetch around them)
};

// Where the N x N Level1 square starts when centred on sample e (as the
// two-level method places it: shifted to stay inside the DEM).
glm::ivec2 level1_square_origin(glm::ivec2 e, int n, int dem_width, int dem_height);

// eye: terrain-local metres; rays: world directions (not necessarily unit),
// e.g. through a grid of pixel centres; max_t: the far distance.
CoveragePrediction predict_level1_coverage(const terrain::Heightfield& hf, const terrain::HeightPyramid& pyramid,
                                           const glm::dvec3& eye, std::span<const glm::dvec3> rays, double max_t,
                                           glm::ivec2 e, const std::vector<int>& ladder);

}  // namespace ig::lod
