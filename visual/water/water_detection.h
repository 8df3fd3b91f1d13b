#pragma once
// Water found in the DEM itself (terrain.water "auto"). No GL.
//
// SRTM's edit (the SRTM Water Body Data) set the sea to exactly 0 m and each
// lake to one constant height, so edited water is a region of one exact
// height that no natural surface has at 30-90 m spacing. What is looked for:
//
//  * flat: samples lying in a 2 x 2 block of four equal heights, joined
//    (4-neighbours) with the same height into regions;
//  * large: at least min_area_m2 (default 600 m x 183 m, the smallest lake
//    the SWBD kept: smaller flat patches were never edited water, and an
//    integer DEM over a plain has plenty of them);
//  * a basin: water cannot stand above land it would run off to, so at
//    most max_lower_share of the region's rim (its samples next to another
//    height) may touch lower ground. A lake's outlet river or a dam's face
//    touches a little (0.6-8 % on the real tiles); the ring of exactly 0 m
//    samples around dry land below sea level (Death Valley) and the flat
//    steps of a dry lake bed (Owens Lake) touch lower ground all along
//    (docs/water.md has the measured shares). The sea may touch more
//    (max_sea_lower_share): coasts have land below sea level behind them;
//  * a shore, not a terrace: at most max_step_share of the rim may rise by
//    1 m or less. Flat farmland and playas in an integer DEM are terraces
//    of 1 m steps all round (Tulare basin 1.00, Owens Lake's lowest flat
//    1.00, Nevada's playas 0.97-1.00); edited lakes have banks (Tahoe 0.28,
//    Mono Lake 0.67, Walker Lake 0.66, Fuji's lakes 0-0.14).
//
// A region at exactly 0 m that reaches the DEM's edge is the sea; every
// other one is a lake. The pass reads the heights row by row (water/
// height_rows.h) twice, keeping one label per run of flat samples, so a
// paged DEM finds exactly the water a whole load does.

#include "terrain/heightfield.h"
#include "water/water_map.h"

namespace ig::water {

struct DetectionRules {
  double min_area_m2 = 600.0 * 183.0;
  double max_lower_share = 0.2;
  double max_sea_lower_share = 0.3;
  double max_step_share = 0.75;
};

// The water in hf (whole or paged). Bodies come in the order their first
// (southernmost, then westernmost) sample is met; source() is "auto".
WaterMap detect_water(const terrain::Heightfield& hf, const DetectionRules& rules = {});

// One flat region as the detection measured it (the tests, and the shares
// docs/water.md lists): every region of at least min_samples, water or not,
// with what decided it.
struct FlatRegion {
  float height_m = 0.0f;
  std::int64_t samples = 0;
  std::int64_t rim = 0;    // samples next to another height
  std::int64_t lower = 0;  // rim samples next to lower ground
  bool touches_edge = false;
  int first_i = 0, first_j = 0;  // its first sample
  std::int64_t steps = 0;  // rim samples on a step of at most 1 m
  bool water = false;
};
std::vector<FlatRegion> flat_regions(const terrain::Heightfield& hf, std::int64_t min_samples,
                                     const DetectionRules& rules = {});

}  // namespace ig::water
