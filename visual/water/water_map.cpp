#include "water/water_map.h"

#include <algorithm>
#include <stdexcept>

namespace ig::water {

const char* water_kind_name(WaterKind kind) {
  switch (kind) {
    case WaterKind::Sea: return "sea";
    case WaterKind::Lake: return "lake";
    case WaterKind::Mapped: return "mapped";
  }
  return "?";
}

WaterMap::WaterMap(int width, int height) : width_(width), height_(height) {
  if (width < 0 || height < 0) throw std::invalid_argument("WaterMap: negative size");
  row_start_.reserve(std::size_t(height) + 1);
}

std::int64_t WaterMap::water_samples() const {
  std::int64_t n = 0;
  for (const WaterRun& r : runs_) n += r.end - r.begin;
  return n;
}

void WaterMap::add_row(int j, std::span<const WaterRun> runs) {
  if (j != rows_added() || j >= height_) throw std::logic_error("WaterMap::add_row: rows must come in order");
  int prev_end = 0;
  for (const WaterRun& r : runs) {
    if (r.begin < prev_end || r.end <= r.begin || r.end > width_ || r.body >= bodies_.size())
      throw std::logic_error("WaterMap::add_row: runs must be sorted, disjoint, inside the row and of known bodies");
    prev_end = r.end;
  }
  runs_.insert(runs_.end(), runs.begin(), runs.end());
  row_start_.push_back(runs_.size());
}

std::span<const WaterRun> WaterMap::row(int j) const {
  if (j < 0 || j >= rows_added()) return {};
  return {runs_.data() + row_start_[j], runs_.data() + row_start_[j + 1]};
}

std::optional<std::uint32_t> WaterMap::body_at(int i, int j) const {
  if (i < 0 || i >= width_) return std::nullopt;
  const std::span<const WaterRun> runs = row(j);
  // The first run ending after i; water if it begins at or before i.
  const auto it = std::upper_bound(runs.begin(), runs.end(), i, [](int x, const WaterRun& r) { return x < r.end; });
  if (it == runs.end() || it->begin > i) return std::nullopt;
  return it->body;
}

void WaterMap::fill_row_mask(int j, std::uint8_t* out) const {
  std::fill(out, out + width_, std::uint8_t(0));
  for (const WaterRun& r : row(j)) std::fill(out + r.begin, out + r.end, std::uint8_t(1));
}

void WaterMap::summarise_bodies(double cell_area_m2) {
  for (WaterBody& b : bodies_) {
    b.samples = 0;
    b.min_i = width_;
    b.min_j = height_;
    b.max_i = b.max_j = -1;
    b.touches_edge = false;
  }
  for (int j = 0; j < rows_added(); ++j)
    for (const WaterRun& r : row(j)) {
      WaterBody& b = bodies_[r.body];
      b.samples += r.end - r.begin;
      b.min_i = std::min(b.min_i, r.begin);
      b.max_i = std::max(b.max_i, r.end - 1);
      b.min_j = std::min(b.min_j, j);
      b.max_j = std::max(b.max_j, j);
      b.touches_edge = b.touches_edge || j == 0 || j == height_ - 1 || r.begin == 0 || r.end == width_;
    }
  for (WaterBody& b : bodies_) b.area_m2 = double(b.samples) * cell_area_m2;
}

bool WaterMap::operator==(const WaterMap& o) const {
  auto same_runs = [](const WaterRun& a, const WaterRun& b) {
    return a.begin == b.begin && a.end == b.end && a.body == b.body;
  };
  auto same_bodies = [](const WaterBody& a, const WaterBody& b) {
    return a.kind == b.kind && a.level_m == b.level_m && a.samples == b.samples && a.min_i == b.min_i &&
           a.min_j == b.min_j && a.max_i == b.max_i && a.max_j == b.max_j && a.touches_edge == b.touches_edge;
  };
  return width_ == o.width_ && height_ == o.height_ && row_start_ == o.row_start_ &&
         std::equal(runs_.begin(), runs_.end(), o.runs_.begin(), o.runs_.end(), same_runs) &&
         std::equal(bodies_.begin(), bodies_.end(), o.bodies_.begin(), o.bodies_.end(), same_bodies);
}

}  // namespace ig::water
