#pragma once
// Nodata (void) filling shared by the whole-array DEM load and the paged
// tile reader (docs/terrain-data.md "Nodata").

#include <cstdint>
#include <climits>
#include <vector>

namespace ig::terrain {

// Fills void samples (state[k] == 0; valid ones are 1) of a w x ht grid
// inward from the edges of each void, one layer at a time: every void sample
// with at least one valid 8-neighbour takes the mean of those neighbours,
// then they all count as valid for the next layer. Deterministic and
// O(samples). Returns the number of void samples (a void with no valid
// sample in the grid stays unfilled).
//
// A sample's layer is its distance in 8-neighbour steps (Chebyshev
// distance) to the nearest valid sample: 0 for valid samples, d for those
// filled in the d-th pass. A layer-d sample depends only on the samples
// within d steps of it, so filling any rectangle that holds its nearest
// valid sample plus d steps around it gives the same value as filling the
// whole grid (the paged reader's halo, terrain/gdal_tile_reader.h). With
// `layers`, it is resized to w * ht and gets each sample's layer
// (kUnfilledLayer for those left unfilled).
constexpr std::int32_t kUnfilledLayer = INT32_MAX;
std::int64_t fill_voids(std::vector<float>& h, std::vector<std::uint8_t>& state, int w, int ht,
                        std::vector<std::int32_t>* layers = nullptr);

}  // namespace ig::terrain
