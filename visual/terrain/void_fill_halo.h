#pragma once
// How far around a rectangle of a DEM the paged tile reader
// (terrain/gdal_tile_reader.h) must read so that filling the voids of that
// window (terrain/void_fill.h) gives the rectangle's samples exactly the
// values a fill of the whole DEM gives them.
//
// Why a window can be exact, from GDAL's algorithm (alg/rasterfill.cpp,
// GDALFillNodata, GDAL 3.6): a top-down and a bottom-up pass record, for
// every column, the nearest valid sample at or above each row and the
// nearest strictly below it, each within D = max_distance rows. A void
// sample p then steps s = 0, 1, 2 ... columns left and right and keeps, in
// each of four quadrants, the nearest of those column candidates (Euclidean
// distance, a later one only when strictly nearer), stopping after step
// floor(largest kept distance), recomputed every 4 steps. Its value is the
// inverse-distance mean of the kept candidates within D. S smoothing passes
// then replace each filled sample by the mean of the valid and filled
// samples of its 3x3 neighbourhood (rows 0 and H - 1 of the grid are never
// smoothed).
//
// So p's interpolated value depends only on the samples within D of it
// (Chebyshev), plus one row, and its smoothed value on those of the filled
// samples within S of it: a halo of D + 1 + S is always exact
// (full_fill_halo). Usually much less is: steps 0 and 1 alone (columns
// p.x and p.x + 1) give every quadrant a candidate at distance at most B,
// the largest of the four, and no later candidate nearer than B can lie more
// than B away; the search stops by step max(4, B). A window holding the
// samples within R = max(4, ceil(B)) + 1 of p therefore keeps exactly the
// candidates the whole grid keeps. exact_fill_halo computes B from the
// window it is given and asks for D + 1 + S wherever a candidate is not in
// the window or is beyond D (a large void).

#include <cstdint>
#include <vector>

#include "terrain/void_fill.h"

namespace ig::terrain {

// A window read from a larger grid and the rectangle inside it whose fill
// must be exact; rows south first, like the heights.
struct FillWindow {
  int width = 0, height = 0;  // the window, samples
  int rect_x0 = 0, rect_y0 = 0, rect_width = 0, rect_height = 0;  // in window samples
  bool east_is_grid_edge = false;  // the window's east column is the grid's
};

// The halo that is exact for any rectangle: D + 1 + S.
int full_fill_halo(const VoidFillOptions& opts);

// The halo (samples beyond the rectangle on each side, clipped at the grid's
// edges) that makes the fill of the rectangle's voids exact, judged from
// the window's validity mask `valid` (width * height, non-zero = valid):
// at least S + 1, at most full_fill_halo(opts). A window with a halo less
// than the answer may not be exact; ask again with the wider window (the
// answer for it is never larger than full_fill_halo).
int exact_fill_halo(const std::vector<std::uint8_t>& valid, const FillWindow& window, const VoidFillOptions& opts);

}  // namespace ig::terrain
