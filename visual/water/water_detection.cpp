#include "water/water_detection.h"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <cstring>
#include <vector>

#include "water/height_rows.h"

namespace ig::water {
namespace {

// A rim sample whose other heights all lie within this of its own is on a
// step of a terraced plain or playa, not on a shore.
constexpr float kStepM = 1.0f;

// A run of flat samples of one height in one row; labels count runs in the
// order they are met, so both passes give a run the same label.
struct FlatRun {
  int begin = 0, end = 0;
  float height = 0.0f;
  std::uint32_t label = 0;
  std::int64_t rim = 0, lower = 0, steps = 0;
};

// Rows j - 1, j, j + 1 of the heightfield, copied (a paged strip may move).
class RowWindow {
 public:
  explicit RowWindow(const terrain::Heightfield& hf) : rows_(hf), w_(hf.width), h_(hf.height) {
    buf_.resize(std::size_t(3) * std::size_t(w_));
  }
  // Moves to row j (called for j = 0, 1, 2, ... in order).
  void advance(int j) {
    if (j == 0) copy(0, 0);
    if (j + 1 < h_) copy(j + 1, (j + 1) % 3);
    j_ = j;
  }
  const float* below() const { return j_ > 0 ? slot((j_ - 1) % 3) : nullptr; }
  const float* here() const { return slot(j_ % 3); }
  const float* above() const { return j_ + 1 < h_ ? slot((j_ + 1) % 3) : nullptr; }

 private:
  void copy(int j, int s) { std::memcpy(buf_.data() + std::size_t(s) * w_, rows_.row(j), sizeof(float) * w_); }
  const float* slot(int s) const { return buf_.data() + std::size_t(s) * w_; }
  HeightRows rows_;
  int w_, h_, j_ = 0;
  std::vector<float> buf_;
};

// The runs of flat samples (in a 2 x 2 block of four equal heights) of the
// window's current row, with each sample's rim and lower-neighbour counts.
void flat_runs(const RowWindow& win, int w, std::uint32_t& next_label, std::vector<FlatRun>& out) {
  out.clear();
  const float* here = win.here();
  const float* below = win.below();
  const float* above = win.above();
  // A 2 x 2 block with its lower-left corner at column i in rows (lo, hi).
  auto block = [w](const float* lo, const float* hi, int i) {
    return lo && hi && i >= 0 && i + 1 < w && lo[i] == lo[i + 1] && lo[i] == hi[i] && lo[i] == hi[i + 1];
  };
  auto flat = [&](int i) {
    return block(below, here, i - 1) || block(below, here, i) || block(here, above, i - 1) || block(here, above, i);
  };
  int i = 0;
  while (i < w) {
    if (!flat(i)) {
      ++i;
      continue;
    }
    FlatRun run;
    run.begin = i;
    run.height = here[i];
    run.label = next_label++;
    for (; i < w && here[i] == run.height && flat(i); ++i) {
      const float h = run.height;
      bool rim = false, lower = false, rise = false;
      auto neighbour = [&](float n) {
        if (n != h) {
          rim = true;
          lower = lower || n < h;
          rise = rise || std::fabs(n - h) > kStepM;
        }
      };
      if (i > 0) neighbour(here[i - 1]);
      if (i + 1 < w) neighbour(here[i + 1]);
      if (below) neighbour(below[i]);
      if (above) neighbour(above[i]);
      run.rim += rim;
      run.lower += lower;
      run.steps += rim && !rise;
    }
    run.end = i;
    out.push_back(run);
  }
}

// Union-find over run labels; a root is its component's smallest label and
// holds the component's totals.
class Regions {
 public:
  void add(const FlatRun& r, int j, int w, int h) {
    parent_.push_back(r.label);
    Totals t;
    t.height = r.height;
    t.samples = r.end - r.begin;
    t.rim = r.rim;
    t.lower = r.lower;
    t.steps = r.steps;
    t.edge = j == 0 || j == h - 1 || r.begin == 0 || r.end == w;
    t.first_i = r.begin;
    t.first_j = j;
    totals_.push_back(t);
  }
  std::uint32_t find(std::uint32_t x) {
    std::uint32_t root = x;
    while (parent_[root] != root) root = parent_[root];
    while (parent_[x] != root) {
      const std::uint32_t next = parent_[x];
      parent_[x] = root;
      x = next;
    }
    return root;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (b < a) std::swap(a, b);
    parent_[b] = a;
    Totals& ta = totals_[a];
    const Totals& tb = totals_[b];
    ta.samples += tb.samples;
    ta.rim += tb.rim;
    ta.lower += tb.lower;
    ta.steps += tb.steps;
    ta.edge = ta.edge || tb.edge;
  }
  struct Totals {
    float height = 0.0f;
    std::int64_t samples = 0, rim = 0, lower = 0, steps = 0;
    bool edge = false;
    int first_i = 0, first_j = 0;
  };
  const Totals& totals(std::uint32_t root) const { return totals_[root]; }
  std::uint32_t size() const { return std::uint32_t(parent_.size()); }

 private:
  std::vector<std::uint32_t> parent_;
  std::vector<Totals> totals_;
};

// Pass 1: every flat region with its totals.
Regions label_regions(const terrain::Heightfield& hf) {
  Regions regions;
  RowWindow win(hf);
  std::vector<FlatRun> prev, cur;
  std::uint32_t next_label = 0;
  for (int j = 0; j < hf.height; ++j) {
    win.advance(j);
    flat_runs(win, hf.width, next_label, cur);
    for (const FlatRun& r : cur) regions.add(r, j, hf.width, hf.height);
    // Runs of one height overlapping the row below are 4-connected.
    std::size_t p = 0;
    for (const FlatRun& r : cur) {
      while (p < prev.size() && prev[p].end <= r.begin) ++p;
      for (std::size_t q = p; q < prev.size() && prev[q].begin < r.end; ++q)
        if (prev[q].height == r.height) regions.unite(prev[q].label, r.label);
    }
    std::swap(prev, cur);
  }
  return regions;
}

bool is_sea(const Regions::Totals& t) { return t.height == 0.0f && t.edge; }

bool is_water(const Regions::Totals& t, double cell_area_m2, const DetectionRules& rules) {
  const double lower_share = is_sea(t) ? rules.max_sea_lower_share : rules.max_lower_share;
  return double(t.samples) * cell_area_m2 >= rules.min_area_m2 && double(t.lower) <= lower_share * double(t.rim) &&
         double(t.steps) <= rules.max_step_share * double(t.rim);
}

}  // namespace

WaterMap detect_water(const terrain::Heightfield& hf, const DetectionRules& rules) {
  WaterMap map(hf.width, hf.height);
  map.set_source("auto");
  if (hf.width < 2 || hf.height < 2) {
    for (int j = 0; j < hf.height; ++j) map.add_row(j, {});
    return map;
  }
  const double cell = hf.spacing_x_m * hf.spacing_y_m;
  Regions regions = label_regions(hf);

  // Bodies in the order of their roots (their first run).
  std::vector<std::int32_t> body_of_root(regions.size(), -1);
  for (std::uint32_t l = 0; l < regions.size(); ++l) {
    if (regions.find(l) != l) continue;
    const Regions::Totals& t = regions.totals(l);
    if (!is_water(t, cell, rules)) continue;
    body_of_root[l] = std::int32_t(map.bodies().size());
    WaterBody b;
    b.kind = is_sea(t) ? WaterKind::Sea : WaterKind::Lake;
    b.level_m = t.height;
    map.bodies().push_back(b);
  }

  // Pass 2: the same runs again, those of water regions written out.
  RowWindow win(hf);
  std::vector<FlatRun> cur;
  std::vector<WaterRun> out;
  std::uint32_t next_label = 0;
  for (int j = 0; j < hf.height; ++j) {
    win.advance(j);
    flat_runs(win, hf.width, next_label, cur);
    out.clear();
    for (const FlatRun& r : cur) {
      const std::int32_t body = body_of_root[regions.find(r.label)];
      if (body < 0) continue;
      if (!out.empty() && out.back().end == r.begin && out.back().body == std::uint32_t(body))
        out.back().end = r.end;
      else
        out.push_back({r.begin, r.end, std::uint32_t(body)});
    }
    map.add_row(j, out);
  }
  map.summarise_bodies(cell);
  return map;
}

std::vector<FlatRegion> flat_regions(const terrain::Heightfield& hf, std::int64_t min_samples,
                                     const DetectionRules& rules) {
  std::vector<FlatRegion> out;
  if (hf.width < 2 || hf.height < 2) return out;
  const double cell = hf.spacing_x_m * hf.spacing_y_m;
  Regions regions = label_regions(hf);
  for (std::uint32_t l = 0; l < regions.size(); ++l) {
    if (regions.find(l) != l) continue;
    const Regions::Totals& t = regions.totals(l);
    if (t.samples < min_samples) continue;
    out.push_back({t.height, t.samples, t.rim, t.lower, t.edge, t.first_i, t.first_j, t.steps, is_water(t, cell, rules)});
  }
  return out;
}

}  // namespace ig::water
