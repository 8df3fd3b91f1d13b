#pragma once
// Nodata (void) filling shared by the whole-array DEM load and the paged
// tile reader (docs/terrain-data.md "Nodata").

#include <cstdint>
#include <vector>

namespace ig::terrain {

// Fills void samples (state[k] == 0; valid ones are 1) of a w x ht grid
// inward from the edges of each void, one layer at a time: every void sample
// with at least one valid 8-neighbour takes the mean of those neighbours,
// then they all count as valid for the next layer. Deterministic and
// O(samples). Returns the number of void samples (a void with no valid
// sample in the grid stays unfilled).
std::int64_t fill_voids(std::vector<float>& h, std::vector<std::uint8_t>& state, int w, int ht);

}  // namespace ig::terrain
