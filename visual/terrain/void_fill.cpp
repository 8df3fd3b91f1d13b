#include "terrain/void_fill.h"

#include <gdal_alg.h>
#include <cpl_error.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "terrain/gdal_support.h"

namespace ig::terrain {

namespace {

template <typename T>
void flip_rows(T* data, int w, int ht) {
  for (int j = 0; j < ht / 2; ++j)
    std::swap_ranges(data + std::ptrdiff_t(j) * w, data + std::ptrdiff_t(j + 1) * w,
                     data + std::ptrdiff_t(ht - 1 - j) * w);
}

// A one-band MEM dataset over `data` (w x ht, row-major): GDAL reads and
// writes the caller's memory, no copy.
gdal::Dataset wrap_in_mem(void* data, GDALDataType type, int w, int ht) {
  gdal::Dataset ds(GDALCreate(GDALGetDriverByName("MEM"), "", w, ht, 0, type, nullptr));
  if (!ds) return ds;
  char pointer[64];
  std::snprintf(pointer, sizeof pointer, "DATAPOINTER=%p", data);
  const char* band_options[] = {pointer, nullptr};
  if (GDALAddBand(gdal::handle(ds), type, const_cast<char**>(band_options)) != CE_None) ds.reset();
  return ds;
}

// GDALFillNodata over heights and mask (both north first; mask 0 = fill).
void gdal_fill(float* heights, std::uint8_t* mask, int w, int ht, const VoidFillOptions& opts) {
  gdal::register_once();
  gdal::QuietErrors quiet;
  CPLErrorReset();
  gdal::Dataset heights_ds = wrap_in_mem(heights, GDT_Float32, w, ht);
  gdal::Dataset mask_ds = wrap_in_mem(mask, GDT_Byte, w, ht);
  if (!heights_ds || !mask_ds)
    throw std::runtime_error("void fill: cannot make in-memory GDAL datasets: " + gdal::last_error("out of memory?"));
  // Its work rasters (and, with smoothing, the copy of the mask it updates
  // as it fills) in memory too: GTiff temporary files otherwise.
  const char* fill_options[] = {"TEMP_FILE_DRIVER=MEM", nullptr};
  if (GDALFillNodata(GDALGetRasterBand(gdal::handle(heights_ds), 1), GDALGetRasterBand(gdal::handle(mask_ds), 1),
                     double(opts.max_distance), 0, opts.smoothing_iterations, const_cast<char**>(fill_options),
                     nullptr, nullptr) != CE_None)
    throw std::runtime_error("void fill (GDALFillNodata) failed: " + gdal::last_error("out of memory?"));
}

// Fills the samples with state 0 (state 1: has a value) inward from their
// edges, one layer at a time: every such sample with at least one 8-neighbour
// that has a value takes the mean of those neighbours, then they all count
// as having one for the next layer. A sample filled in pass d gets layer d
// in `layers` (if given); those with no value anywhere keep kUnfilledLayer.
void fill_by_layers(std::vector<float>& h, std::vector<std::uint8_t>& state, int w, int ht,
                    std::vector<std::int32_t>* layers) {
  auto for_neighbours = [&](std::uint32_t k, auto&& fn) {
    const int i = int(k % std::uint32_t(w)), j = int(k / std::uint32_t(w));
    for (int dj = -1; dj <= 1; ++dj) {
      const int jj = j + dj;
      if (jj < 0 || jj >= ht) continue;
      for (int di = -1; di <= 1; ++di) {
        const int ii = i + di;
        if ((di == 0 && dj == 0) || ii < 0 || ii >= w) continue;
        fn(std::uint32_t(jj) * std::uint32_t(w) + std::uint32_t(ii));
      }
    }
  };
  // state: 0 to fill, 1 has a value, 2 queued for the next layer.
  std::vector<std::uint32_t> frontier, next;
  for (std::uint32_t k = 0; k < state.size(); ++k) {
    if (state[k] != 0) continue;
    if (layers) (*layers)[k] = kUnfilledLayer;
    bool near_value = false;
    for_neighbours(k, [&](std::uint32_t n) { near_value |= (state[n] == 1); });
    if (near_value) {
      state[k] = 2;
      frontier.push_back(k);
    }
  }
  std::vector<float> values;
  for (std::int32_t layer = 1; !frontier.empty(); ++layer) {
    values.resize(frontier.size());
    for (std::size_t f = 0; f < frontier.size(); ++f) {
      double sum = 0.0;
      int count = 0;
      for_neighbours(frontier[f], [&](std::uint32_t n) {
        if (state[n] == 1) {
          sum += h[n];
          ++count;
        }
      });
      values[f] = float(sum / std::max(count, 1));
    }
    next.clear();
    for (std::size_t f = 0; f < frontier.size(); ++f) {
      h[frontier[f]] = values[f];
      state[frontier[f]] = 1;
      if (layers) (*layers)[frontier[f]] = layer;
    }
    for (std::uint32_t k : frontier)
      for_neighbours(k, [&](std::uint32_t n) {
        if (state[n] == 0) {
          state[n] = 2;
          next.push_back(n);
        }
      });
    frontier.swap(next);
  }
}

// Each sample's distance in 8-neighbour steps (Chebyshev) to the nearest
// valid sample, capped at `cap`: two raster passes over the grid.
std::vector<std::uint16_t> steps_to_valid(const std::vector<std::uint8_t>& valid, int w, int ht, std::uint16_t cap) {
  std::vector<std::uint16_t> d(valid.size());
  auto at = [&](int i, int j) -> std::uint16_t& { return d[std::size_t(j) * w + i]; };
  auto relax = [&](std::uint16_t& v, int i, int j) {
    if (i >= 0 && i < w && j >= 0 && j < ht) v = std::min<std::uint16_t>(v, std::uint16_t(at(i, j) + 1));
  };
  for (int j = 0; j < ht; ++j)
    for (int i = 0; i < w; ++i) {
      std::uint16_t& v = at(i, j);
      v = valid[std::size_t(j) * w + i] ? 0 : cap;
      relax(v, i - 1, j), relax(v, i - 1, j - 1), relax(v, i, j - 1), relax(v, i + 1, j - 1);
      v = std::min(v, cap);
    }
  for (int j = ht - 1; j >= 0; --j)
    for (int i = w - 1; i >= 0; --i) {
      std::uint16_t& v = at(i, j);
      relax(v, i + 1, j), relax(v, i + 1, j + 1), relax(v, i, j + 1), relax(v, i - 1, j + 1);
      v = std::min(v, cap);
    }
  return d;
}

}  // namespace

VoidFillResult fill_voids(std::vector<float>& h, const std::vector<std::uint8_t>& valid, int w, int ht,
                          const VoidFillOptions& opts, std::vector<std::int32_t>* deep_layers) {
  if (opts.max_distance < 1 || opts.max_distance > VoidFillOptions::kMaxVoidSearch)
    throw std::invalid_argument("void fill: max_distance must be 1.." + std::to_string(VoidFillOptions::kMaxVoidSearch));
  if (opts.smoothing_iterations < 0 || opts.smoothing_iterations > VoidFillOptions::kMaxVoidSmoothing)
    throw std::invalid_argument("void fill: smoothing_iterations must be 0.." +
                                std::to_string(VoidFillOptions::kMaxVoidSmoothing));
  const std::size_t n = std::size_t(w) * std::size_t(ht);
  VoidFillResult result;
  for (std::size_t k = 0; k < n; ++k) result.voids += valid[k] == 0;
  if (deep_layers) deep_layers->assign(n, 0);
  if (result.voids == 0) return result;

  // NaN marks what GDAL leaves unfilled: it reads only samples the mask
  // calls valid (or has filled), so a NaN never spreads.
  constexpr float kLeft = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t k = 0; k < n; ++k)
    if (!valid[k]) h[k] = kLeft;
  if (std::size_t(result.voids) < n) {
    // GDAL searches every masked sample up to max_distance columns each
    // way until it has a candidate in all four quadrants, so the middle of
    // a large void costs it the most and gives nothing. Void samples more
    // than 2 * max_distance + smoothing + 1 steps from every valid sample
    // are handed over as valid NaNs instead: no sample GDAL can fill
    // (within max_distance of valid data), nor one a smoothing pass reads
    // for it (within smoothing of those), lies within max_distance of
    // them, so they are never its candidates, and the samples that do find
    // them are deep ones, which come out NaN as they would have anyway.
    const int far = 2 * opts.max_distance + opts.smoothing_iterations + 1;
    const std::vector<std::uint16_t> steps = steps_to_valid(valid, w, ht, std::uint16_t(far + 1));
    std::vector<std::uint8_t> mask(n);  // north first, as the file
    for (int r = 0; r < ht; ++r) {
      const std::size_t src = std::size_t(ht - 1 - r) * w, dst = std::size_t(r) * w;
      for (int i = 0; i < w; ++i) mask[dst + i] = valid[src + i] || steps[src + i] > far ? 255 : 0;
    }
    flip_rows(h.data(), w, ht);
    try {
      gdal_fill(h.data(), mask.data(), w, ht, opts);
    } catch (...) {
      flip_rows(h.data(), w, ht);
      throw;
    }
    flip_rows(h.data(), w, ht);
  }

  for (std::size_t k = 0; k < n; ++k) result.deep += !valid[k] && std::isnan(h[k]);
  if (result.deep == 0) return result;
  std::vector<std::uint8_t> state(n);
  for (std::size_t k = 0; k < n; ++k) state[k] = valid[k] || !std::isnan(h[k]);
  fill_by_layers(h, state, w, ht, deep_layers);
  return result;
}

}  // namespace ig::terrain
