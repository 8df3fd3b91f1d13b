#pragma once
// The lowest the drawn terrain ever is over each cell of a coarse grid, for
// occlusion culling (lod/horizon_culling.h): everything under a cell's floor
// is solid, whichever surface is drawn there. Two-level draws Level0 outside
// Level1's square and the full-resolution grid inside it, so the floor is the
// lower of the DEM's minimum over the cell (the min/max pyramid; between
// samples the grid is linear) and Level0's lowest point over the cell (each
// triangle clipped to the cell: a plane's minimum over a polygon is at one of
// its corners). Built once at load; no GL.

#include <vector>

#include "lod/roam_level0_mesh.h"
#include "terrain/height_pyramid.h"

namespace ig::lod {

struct TerrainFloors {
  int cell_samples = 0;  // a cell spans cell_samples x cell_samples grid cells
  int nx = 0, ny = 0;    // cells in x and y
  int grid_cells_x = 0, grid_cells_y = 0;  // the DEM's grid cells (width-1, height-1): the last row and column of cells may be narrower
  std::vector<float> floor_m;
  // Per cell: the longest diagonal, in samples, of a drawn triangle's box
  // over it (empty: the floors take no sag into account). The renderer lowers each
  // vertex by the Earth's curvature and interpolates between them, so a
  // triangle of chord L sags under the curved surface by up to L^2 / 8R.
  std::vector<float> chord_samples;
  float at(int i, int j) const { return floor_m[size_t(j) * nx + i]; }
};

// Cells of 2^cell_level pyramid cells (the pyramid's level-cell_level nodes).
// Level0's sample indices must be the pyramid's (the DEM's) samples.
TerrainFloors terrain_floors(const Level0Mesh& level0, const terrain::HeightPyramid& pyramid, int cell_level);

}  // namespace ig::lod
