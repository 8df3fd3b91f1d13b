#pragma once
// Horizon culling (lod/horizon_culling.h) for any method, over the boxes it
// draws this frame: geomipmap blocks, chunks, CDLOD nodes, or groups of a
// per-frame triangle list (ROAM, quadtree). The occluders are the drawn
// surface itself: every box's bottom is at or under what the method draws
// over the box's footprint (vertices are DEM samples inside it, and a plane's
// lowest point over a region is at a vertex), so under each cell of a coarse
// grid everything below the lowest bottom of the boxes over that cell is
// solid. Cells no box covers hold nothing: they lie outside the view volume
// (a line of sight to a point in view stays in view) or off the DEM.
//
// Why: the two-level method culls with its own floors; the same test over
// each baseline's own boxes keeps Table 2 a comparison of LOD methods, not of
// culling. The picture is the same with and without it. No GL here.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/gtc/type_precision.hpp>

#include "lod/horizon_culling.h"
#include "terrain/height_pyramid.h"
#include "terrain/heightfield.h"

namespace ig::lod {

class DrawnSurfaceOcclusion {
 public:
  // Occluder cells of cell_samples x cell_samples grid cells over hf.
  // pyramid: hf's min/max pyramid (dem_max_near).
  DrawnSurfaceOcclusion(const terrain::Heightfield& hf, const terrain::HeightPyramid& pyramid, int cell_samples = 32);

  // boxes: this frame's drawn pieces in terrain-local metres, lo.z at or
  // under the drawn surface over the footprint, hi.z at or over it.
  // surface_at_eye_m: at or over the drawn surface straight under the eye
  // (-infinity where nothing is drawn there). hidden[k] = 1 where boxes[k]
  // is hidden from `eye` by the others; none unless the eye is above that
  // surface (a line from under it could leave through a back face). Boxes
  // nearer than min_distance_m horizontally are never hidden. Returns how
  // many are.
  int mark_hidden(const glm::dvec3& eye, double earth_radius_m, double min_distance_m,
                  const std::vector<HorizonCulling::Box>& boxes, std::vector<std::uint8_t>& hidden,
                  double surface_at_eye_m);

  // The highest DEM sample within radius_samples of the eye's sample
  // (horizontally; clamped to the DEM): over the drawn surface under the eye
  // for a grid piece whose triangles span at most that many samples.
  double dem_max_near(const glm::dvec3& eye, int radius_samples) const;

  // The same for a triangle list of DEM sample indices (3 per triangle,
  // heights from hf): triangles are grouped by the cell holding their
  // centroid, each group a box; the hidden groups' triangles are removed,
  // the others keep their order. The surface under the eye is bounded by the
  // triangles over it. Returns the groups hidden.
  int cull_triangles(const glm::dvec3& eye, double earth_radius_m, double min_distance_m,
                     std::vector<glm::u16vec2>& vertices);

  // The same for a list of drawn pieces: box_of(piece) gives its box,
  // span_of(piece) the samples its drawn triangles span at most, which
  // bounds the drawn surface under the eye by the DEM (dem_max_near) over
  // the pieces whose footprint holds the eye. The hidden pieces are
  // removed, the others keep their order.
  template <class Piece, class BoxOf, class SpanOf>
  int remove_hidden(const glm::dvec3& eye, double earth_radius_m, double min_distance_m, std::vector<Piece>& pieces,
                    BoxOf box_of, SpanOf span_of) {
    boxes_.clear();
    int span = 0;
    for (const Piece& p : pieces) {
      const HorizonCulling::Box& b = boxes_.emplace_back(box_of(p));
      if (eye.x >= b.lo.x && eye.x <= b.hi.x && eye.y >= b.lo.y && eye.y <= b.hi.y) span = std::max(span, span_of(p));
    }
    const double surface = span > 0 ? dem_max_near(eye, span) : -std::numeric_limits<double>::infinity();
    const int count = mark_hidden(eye, earth_radius_m, min_distance_m, boxes_, hidden_, surface);
    if (count == 0) return 0;
    size_t kept = 0;
    for (size_t k = 0; k < pieces.size(); ++k)
      if (!hidden_[k]) pieces[kept++] = std::move(pieces[k]);
    pieces.resize(kept);
    return count;
  }

 private:
  const terrain::Heightfield& hf_;
  const terrain::HeightPyramid& pyramid_;
  int cell_samples_;
  HorizonCulling culling_;
  // Per frame (cull_triangles): the group of each triangle, and per cell its
  // group (-1: none yet).
  std::vector<std::int32_t> group_of_cell_, group_of_triangle_;
  std::vector<HorizonCulling::Box> groups_, boxes_;
  std::vector<std::uint8_t> hidden_;
};

}  // namespace ig::lod
