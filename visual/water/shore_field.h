#pragma once
// The shoreline between samples, one definition for the picture and the host
// queries. No GL.
//
// The water map says which samples are water: a coast at any angle is a
// staircase of whole samples there. Each sample gets the share of water
// around it instead: the mask blurred by a small Gaussian (kShoreSigma
// samples), which is 1 inside the water, 0 on land and falls through 1/2
// where the staircase's mean line runs. Interpolated bilinearly, the line
// where it is 1/2 is the shore: straight along a straight coast at any angle,
// round at a corner, never the cells' stair-steps. It is stored in a byte
// (the water texture, and quantised alike for the queries); its mips are the
// share of water a distant pixel covers.

#include <cstdint>
#include <functional>
#include <optional>

#include "water/water_map.h"

namespace ig::water {

inline constexpr double kShoreSigma = 1.0;  // samples  // samples  // samples  // samples  // samples
inline constexpr int kShoreRadius = 3;      // the blur's taps: -3 .. 3

std::uint8_t shore_byte(double share);  // [0, 1] -> 0 .. 255, rounded
float shore_from_byte(std::uint8_t byte);

// The grid of every step-th sample (step 1: the DEM's own; step > 1: an
// overview's, blurred in its own samples).
struct ShoreGrid {
  int width = 0, height = 0, step = 1;
};
ShoreGrid shore_grid(const WaterMap& map, int step);
// The shares as bytes, row by row over that grid, with the water mask (0 /
// 255) beside them: calls row(j, share, mask) for j = 0 .. height - 1.
// Beyond the DEM's edge the edge sample's water is taken to go on.
void for_each_shore_row(const WaterMap& map, int step,
                        const std::function<void(int j, const std::uint8_t* share, const std::uint8_t* mask)>& row);
// Sample (i, j)'s share (unquantised; the rows above are it quantised).
double shore_share_at_sample(const WaterMap& map, int i, int j);

// The shore at a point in sample coordinates (si, sj): the share
// interpolated from the four samples around it (each quantised as stored);
// water where it is at least 1/2, of the body of the nearest water sample.
// nullopt outside the grid or for a non-finite point.
struct ShorePoint {
  float share = 0.0f;
  std::optional<std::uint32_t> body;  // set when share >= 0.5
  bool water() const { return share >= 0.5f; }
};
std::optional<ShorePoint> shore_at(const WaterMap& map, double si, double sj);

}  // namespace ig::water
