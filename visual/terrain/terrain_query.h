#pragma once
// Height of terrain and line of sight answered from the surface the renderer
// draws at full resolution: every DEM sample a vertex, each cell (i,j)-(i+1,j+1)
// split along that diagonal into (i,j),(i+1,j),(i+1,j+1) and
// (i,j),(i+1,j+1),(i,j+1) (render/grid_mesh.cpp, shaders/terrain_grid.vert,
// Heightfield::sample_surface, terrain/ray_cast.h). No GL, no sockets.
//
// Frame: terrain-local metres (x east, y north, z up; Heightfield). Heights
// are the DEM's (metres above its vertical datum); a HAT is alt - HOT.
//
// Earth curvature (terrain/earth_curvature.h): with a radius R > 0 the
// renderer lowers every sample by drop(d) below the eye's tangent plane, d its
// horizontal distance from the eye. A line of sight is answered as drawn for
// an eye at its source point: the line is straight in the source's tangent
// frame and meets the triangles between the lowered samples
// (terrain/ray_cast.h, Curvature). Hit points are given back in the flat DEM
// frame (the same x, y; z the DEM's height there). HOT needs no curvature: a
// point's height is the DEM's wherever the eye is.

#include <memory>
#include <optional>

#include <glm/vec3.hpp>

#include "terrain/height_pyramid.h"
#include "terrain/heightfield.h"
#include "terrain/surface_material.h"

namespace ig::terrain {

struct SurfacePoint {
  double height_m;    // the drawn surface's height at (x, y); over water the water's level
  glm::dvec3 normal;  // unit, z > 0, of the triangle under (x, y); over water straight up
  int cell_i, cell_j;
  SurfaceMaterial material = SurfaceMaterial::Land;
};

struct LosHit {
  double range_m;     // from the source, along the line (metres)
  glm::dvec3 point;   // terrain-local (flat DEM frame: z is the DEM height there, or the water's level)
  glm::dvec3 normal;  // unit normal of the triangle hit (flat DEM frame); straight up on water
  SurfaceMaterial material = SurfaceMaterial::Land;
};

class TerrainQuery {
 public:
  // Builds the min/max pyramid (about 0.1 s and 5.6 MB for 4097 x 4097).
  // hf must outlive the query and not change. earth_radius_m <= 0: flat.
  TerrainQuery(const Heightfield& hf, double earth_radius_m);
  // Uses a pyramid built from hf already (the scene's), which must outlive
  // the query. Throws std::invalid_argument when its size does not match.
  TerrainQuery(const Heightfield& hf, const HeightPyramid& pyramid, double earth_radius_m);

  // The drawn surface at (x, y); nullopt outside the DEM footprint
  // [0, extent_x] x [0, extent_y] or for non-finite input. On a cell's
  // diagonal or edge both triangles give the same height; the normal is
  // either one's.
  std::optional<SurfacePoint> surface_at(double x_m, double y_m) const;

  // Starts fetching the samples surface_at(x, y) will read: a batch of
  // scattered queries prefetched first waits on memory once, not per query.
  void prefetch(double x_m, double y_m) const;

  // First point of the terrain on the segment from -> to (from's end
  // first); nullopt when the segment is clear, leaves the footprint before
  // meeting terrain, or the input is not finite. A source under the terrain
  // hits at range 0 only if it is on the surface; otherwise where the line
  // first crosses the surface.
  std::optional<LosHit> segment(const glm::dvec3& from, const glm::dvec3& to) const;

  // First point of the terrain along dir (need not be unit; in the source's
  // tangent frame, i.e. the flat frame's axes) with min_range_m <= range <=
  // max_range_m. nullopt on a miss, a zero dir, min > max, or non-finite input.
  std::optional<LosHit> ray(const glm::dvec3& from, const glm::dvec3& dir, double min_range_m,
                            double max_range_m) const;

  const Heightfield& heightfield() const { return hf_; }
  double earth_radius_m() const { return earth_radius_m_; }
  bool inside(double x_m, double y_m) const;

 private:
  // The nearest crossing of the line from `from` along unit `d` (ranges
  // [min, max]) with a water body's surface that is water there; nullopt
  // when it meets none.
  std::optional<LosHit> water_hit(const glm::dvec3& from, const glm::dvec3& d, double min_range_m,
                                  double max_range_m) const;

  const Heightfield& hf_;
  std::unique_ptr<HeightPyramid> owned_pyramid_;
  const HeightPyramid& pyramid_;
  double earth_radius_m_ = 0.0;
};

}  // namespace ig::terrain
