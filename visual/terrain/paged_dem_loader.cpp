#include "terrain/paged_dem_loader.h"

#include <algorithm>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

#include "terrain/height_pyramid.h"
#include "terrain/heightfield_overview.h"
#include "terrain/paged_heights.h"

namespace ig::terrain {

Heightfield load_paged_heights(const std::string& path, const SampleDecoding& decoding,
                               const VoidFillOptions& void_fill, std::size_t budget_bytes, int tile) {
  auto reader = std::make_shared<GdalTileReader>(path, decoding, void_fill);
  const int w = reader->width(), ht = reader->height();
  tile = std::max(tile, 4);

  Heightfield hf;
  hf.width = w;
  hf.height = ht;
  hf.source = path;

  const int step = overview_step_for(w, ht, kPagedOverviewSide);
  auto overview = std::make_shared<Heightfield>();
  overview->width = (w - 1) / step + 1;
  overview->height = (ht - 1) / step + 1;
  overview->heights.resize(static_cast<std::size_t>(overview->width) * overview->height);

  // Level-2 pyramid nodes (exact min/max over 5 x 5 samples, sharing edges):
  // row j of samples feeds node row j / 4, and node row j / 4 - 1 too when
  // j is a multiple of 4.
  using MinMax = HeightPyramid::MinMax;
  const int n2x = HeightPyramid::level2_side(w), n2y = HeightPyramid::level2_side(ht);
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<MinMax> level2(static_cast<std::size_t>(n2x) * n2y, MinMax{inf, -inf});
  std::vector<MinMax> row_nodes(n2x);

  float lo = inf, hi = -inf;
  double sum = 0.0;
  std::int64_t voids = 0, deep = 0, inexact = 0;
  std::vector<float> strip(static_cast<std::size_t>(w) * tile), part;
  for (int y0 = 0; y0 < ht; y0 += tile) {
    const int h = std::min(tile, ht - y0);
    // Tile by tile, exactly as the cache will read them, so the statistics,
    // overview and pyramid are those of the samples the tiles serve (voids
    // are filled per tile, from a halo around it: gdal_tile_reader.h).
    for (int x0 = 0; x0 < w; x0 += tile) {
      const int tw = std::min(tile, w - x0);
      part.resize(static_cast<std::size_t>(tw) * h);
      const TileVoids v = reader->read(x0, y0, tw, h, part.data());
      voids += v.filled;
      deep += v.deep;
      inexact += v.inexact;
      for (int r = 0; r < h; ++r)
        std::copy_n(part.data() + std::size_t(r) * tw, tw, strip.data() + std::size_t(r) * w + x0);
    }
    for (int r = 0; r < h; ++r) {
      const float* row = strip.data() + std::size_t(r) * w;
      const int j = y0 + r;
      for (int i = 0; i < w; ++i) {
        lo = std::min(lo, row[i]);
        hi = std::max(hi, row[i]);
        sum += row[i];
      }
      if (j % step == 0) {
        float* o = overview->heights.data() + std::size_t(j / step) * overview->width;
        for (int k = 0; k < overview->width; ++k) o[k] = row[k * step];
      }
      for (int n = 0; n < n2x; ++n) {
        const int i1 = std::min(4 * n + 4, w - 1);
        MinMax m{row[4 * n], row[4 * n]};
        for (int i = 4 * n + 1; i <= i1; ++i) {
          m.lo = std::min(m.lo, row[i]);
          m.hi = std::max(m.hi, row[i]);
        }
        row_nodes[n] = m;
      }
      for (const int node_row : {j / 4, j % 4 == 0 ? j / 4 - 1 : -1}) {
        if (node_row < 0 || node_row >= n2y) continue;
        MinMax* dst = level2.data() + std::size_t(node_row) * n2x;
        for (int n = 0; n < n2x; ++n) {
          dst[n].lo = std::min(dst[n].lo, row_nodes[n].lo);
          dst[n].hi = std::max(dst[n].hi, row_nodes[n].hi);
        }
      }
    }
  }
  if (voids == static_cast<std::int64_t>(w) * ht)
    throw std::runtime_error("all " + std::to_string(std::int64_t(w) * ht) + " samples are nodata");
  strip = {};
  part = {};

  hf.min_m = lo;
  hf.max_m = hi;
  hf.mean_m = sum / (double(w) * double(ht));
  hf.nodata_count = voids;
  hf.deep_void_count = deep;
  hf.void_fill = void_fill;

  overview->finalize_stats();
  overview->source = path + " (overview, every " + std::to_string(step) + " samples)";

  auto cache = std::make_shared<HeightTileCache>(
      w, ht, tile, budget_bytes, [reader](int, int, int x0, int y0, int tw, int th, float* out) {
        reader->read(x0, y0, tw, th, out);
      });
  auto paged = std::make_shared<PagedHeights>();
  paged->cache = cache;
  paged->overview = overview;
  paged->overview_step = step;
  paged->inexact_voids = inexact;
  paged->pyramid = std::make_shared<const HeightPyramid>(HeightPyramid::from_level2(w, ht, cache, level2, {lo, hi}));
  hf.paged = paged;
  return hf;
}

}  // namespace ig::terrain
