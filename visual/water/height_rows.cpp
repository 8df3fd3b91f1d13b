#include "water/height_rows.h"

#include <algorithm>
#include <stdexcept>

#include "terrain/paged_heights.h"

namespace ig::water {

HeightRows::HeightRows(const terrain::Heightfield& hf) : hf_(hf) {
  if (!hf.has_samples()) throw std::invalid_argument(hf.source + ": no heights to read");
}

const float* HeightRows::row(int j) {
  if (j < 0 || j >= hf_.height) throw std::out_of_range("HeightRows::row: row outside the grid");
  if (hf_.has_whole_heights()) return hf_.heights.data() + std::size_t(j) * std::size_t(hf_.width);
  if (j < strip_first_ || j >= strip_first_ + strip_rows_) {
    // A strip of whole tile rows, so every tile is read once per pass.
    const terrain::HeightTileCache& cache = *hf_.paged->cache;
    const int t = cache.tile_size();
    strip_first_ = j / t * t;
    strip_rows_ = std::min(t, hf_.height - strip_first_);
    strip_.resize(std::size_t(strip_rows_) * std::size_t(hf_.width));
    cache.read_rect(0, strip_first_, hf_.width, strip_rows_, strip_.data(), std::size_t(hf_.width));
  }
  return strip_.data() + std::size_t(j - strip_first_) * std::size_t(hf_.width);
}

}  // namespace ig::water
