#include "lod/twolevel_selection.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "lod/band_ring.h"
#include "lod/level1_coverage_predictor.h"
#include "lod/level1_selection.h"
#include "lod/terrain_floors.h"
#include "terrain/back_faces_hidden.h"
#include "terrain/height_tile_cache.h"

namespace ig::lod {
namespace {

// Horizon culling's occluder cells: 2^4 = 16 samples a side near the eye,
// coarser where a cell would span more than 64 of the 2048 directions. On the
// Table 2 flight this hides as many clusters as 32-sample cells everywhere,
// for about 0.2 ms less a frame (docs/twolevel.md).
constexpr int kFloorCellLevel = 4;
constexpr double kBinsPerWholeCell = 64.0;

// Whether any part of the terrain can be in view: the view against the
// min/max pyramid's boxes, descending to nodes of 64 cells. The single
// whole-DEM box is too coarse (it always straddles the planes through the eye).
bool terrain_in_view(const terrain::HeightPyramid& p, const terrain::Heightfield& hf, const TwoLevelView& view,
                     int level, int i, int j) {
  const int size = 1 << level;
  const int i0 = i * size, j0 = j * size;
  const int i1 = std::min(i0 + size, p.cells_x()), j1 = std::min(j0 + size, p.cells_y());
  const auto mm = p.node(level, i, j);
  const glm::dvec3 lo(i0 * hf.spacing_x_m, j0 * hf.spacing_y_m, mm.lo), hi(i1 * hf.spacing_x_m, j1 * hf.spacing_y_m, mm.hi);
  if (!view.box_in_view(lo - view.position, hi - view.position)) return false;
  if (level == 0 || size <= 64) return true;
  for (int cj = 2 * j; cj <= 2 * j + 1 && cj < p.level_height(level - 1); ++cj)
    for (int ci = 2 * i; ci <= 2 * i + 1 && ci < p.level_width(level - 1); ++ci)
      if (terrain_in_view(p, hf, view, level - 1, ci, cj)) return true;
  return false;
}

}  // namespace

std::vector<glm::ivec2> level1_perimeter(int n) {
  std::vector<glm::ivec2> perimeter;
  for (int i = 0; i < n - 1; ++i) perimeter.push_back({i, 0});
  for (int j = 0; j < n - 1; ++j) perimeter.push_back({n - 1, j});
  for (int i = n - 1; i > 0; --i) perimeter.push_back({i, n - 1});
  for (int j = n - 1; j > 0; --j) perimeter.push_back({0, j});
  return perimeter;
}

TwoLevelSelector::TwoLevelSelector(const terrain::Heightfield& hf, const terrain::HeightPyramid& pyramid,
                                   Level0Mesh level0, const options::TwoLevelOptions& options)
    : hf_(hf),
      pyramid_(pyramid),
      options_(options),
      level0_(std::move(level0)),
      level0_heights_(level0_, hf.width, hf.height),
      controller_(level1_ladder(hf.width, hf.height, options.max_level1),
                  SizeControllerOptions{options.a1, options.a2}) {
  level0_resolution_ = double(level0_.samples.size()) / (double(hf.width) * hf.height);
  const glm::dvec2 spacing(hf.spacing_x_m, hf.spacing_y_m);
  clusters_ = std::make_unique<Level0Clusters>(level0_, spacing);
  // Every height the walls can take: the DEM's (its statistics and its
  // pyramid's root) and Level0's (lifted or not).
  terrain_z_lo_ = hf.min_m;
  terrain_z_hi_ = hf.max_m;
  if (!pyramid_.empty()) {
    const auto root = pyramid_.node(pyramid_.num_levels() - 1, 0, 0);
    terrain_z_lo_ = std::min(terrain_z_lo_, double(root.lo));
    terrain_z_hi_ = std::max(terrain_z_hi_, double(root.hi));
  }
  for (const auto& p : level0_.positions) {
    terrain_z_lo_ = std::min(terrain_z_lo_, double(p.z));
    terrain_z_hi_ = std::max(terrain_z_hi_, double(p.z));
  }
  if (options_.horizon_culling && !pyramid_.empty())
    horizon_ = std::make_unique<HorizonCulling>(terrain_floors(level0_, pyramid_, kFloorCellLevel), spacing,
                                                kBinsPerWholeCell);
}

bool TwoLevelSelector::place_level1(const TwoLevelView& view, double ratio, const glm::dvec2& eye,
                                    const Level1Paging& paging) {
  // Paged heights, live: after the first frame nothing here waits on a
  // tile. Reads go through resident-only views that queue what is missing
  // and count it; a square whose heights (square, band, height window) are
  // not all in is refused. Either way Level1 keeps last frame's square
  // until they are.
  const bool no_wait = paging.no_wait && sel_.n > 0;
  terrain::TileMisses misses;
  std::optional<terrain::Heightfield> hf_view;
  std::optional<terrain::HeightPyramid> pyramid_view;
  if (no_wait && hf_.paged) {
    hf_view.emplace(hf_.resident_only(misses));
    pyramid_view.emplace(pyramid_.resident_only(misses));
  }
  const terrain::Heightfield& hf = hf_view ? *hf_view : hf_;
  const terrain::HeightPyramid& pyramid = pyramid_view ? *pyramid_view : pyramid_;
  {
    const LookAtPoint e =
        find_look_at_point(hf, pyramid, view.position, view.forward, view.up, view.earth_radius_m);
    // Snap E to a whole sample and keep the square inside the DEM.
    const glm::ivec2 ec{int(std::lround(e.point.x / hf.spacing_x_m)), int(std::lround(e.point.y / hf.spacing_y_m))};
    const double eye_agl =
        options_.eye_guard ? view.position.z - hf.sample_bilinear(view.position.x, view.position.y) : 0.0;
    if (misses.count > 0) return false;
    int n = 0;
    // Level1 is worth its vertices only where Level0's error would show. When
    // even the largest square around E reaches no terrain nearer than where
    // Level0's largest error is under kFarLevel0ErrorPx (E far out: a range
    // beyond a ridge, the horizon), Level1 takes the smallest size and the
    // size controller waits: a larger square would cost vertices for a few pixels.
    const double reach = 0.5 * std::sqrt(2.0) * (controller_.ladder().back() - 1) *
                         std::max(hf.spacing_x_m, hf.spacing_y_m);  // E to the corners of the largest square
    const double nearest = glm::length(e.point - view.position) - reach;
    const bool far = nearest > 0.0 && level0_.max_error_m * view.pixels_per_radian < kFarLevel0ErrorPx * nearest;
    if (far) {
      n = controller_.ladder().front();
    } else if (options_.predict_size && sel_.terrain_visible) {
      // R for every ladder size on a 12 x 9 grid of view rays (about 0.1-0.3 ms).
      constexpr int kRaysX = 12, kRaysY = 9;
      prediction_rays_.clear();
      for (int y = 0; y < kRaysY; ++y)
        for (int x = 0; x < kRaysX; ++x)
          prediction_rays_.push_back(
              view.pixel_ray((x + 0.5) * view.viewport.x / kRaysX, (y + 0.5) * view.viewport.y / kRaysY));
      auto p = predict_level1_coverage(hf, pyramid, view.position, prediction_rays_, view.far_m, ec,
                                       controller_.ladder());
      if (misses.count > 0) return false;  // before the controller moves
      // Paged heights: keep the tiles under the view resident.
      auto& points = sel_.scene_requests.points_m;
      points.insert(points.end(), p.hits.begin(), p.hits.end());
      n = controller_.update(ratio, p.ratio);
    } else {
      n = controller_.update(ratio);
    }
    // Far out, the small square goes under the eye instead (over the DEM),
    // so the eye guard need not grow it to the largest to reach from E.
    const bool eye_on_dem = eye.x >= 0 && eye.y >= 0 && eye.x <= hf.width - 1 && eye.y <= hf.height - 1;
    Level1Placement place{n, far && eye_on_dem ? glm::ivec2(glm::round(eye)) : ec, false};
    if (options_.eye_guard)
      place = guard_level1_for_eye(place, eye, eye_agl, level0_.max_error_m, controller_.ladder(),
                                   {hf.width, hf.height});
    const glm::ivec2 origin = level1_square_origin(place.centre, place.n, hf.width, hf.height);
    if (no_wait && paging.ready) {
      const int band = band_width_samples(level0_resolution_, options_.alpha, place.n, options_.band_stride);
      if (!paging.ready(origin - band, origin + (place.n - 1) + band, origin + (place.n - 1) / 2)) return false;
    }
    sel_.look_at = e;
    sel_.far = far;
    sel_.eye_guarded = place.eye_guarded;
    sel_.n = place.n;
    sel_.origin = origin;
    return true;
  }
}

const TwoLevelSelection& TwoLevelSelector::select(const TwoLevelView& view, double ratio, const Level1Paging& paging) {
  const auto& hf = hf_;
  sel_.scene_requests = {};
  sel_.terrain_visible = !pyramid_.empty() && terrain_in_view(pyramid_, hf, view, pyramid_.num_levels() - 1, 0, 0);
  if (ratio >= 0.0) sel_.last_ratio = ratio;

  const glm::dvec2 eye(view.position.x / hf.spacing_x_m, view.position.y / hf.spacing_y_m);
  sel_.scene_requests.sample_rects.push_back({glm::ivec2(eye), glm::ivec2(eye)});  // the ground under the eye
  sel_.held = !place_level1(view, ratio, eye, paging);
  const int n = sel_.n;
  sel_.scene_requests.window_centre = sel_.origin + (n - 1) / 2;  // the height window, if any, on Level1
  sel_.band_w = band_width_samples(level0_resolution_, options_.alpha, n, options_.band_stride);
  // Paged heights: Level1's square and band (their bounds read the finest
  // pyramid levels along the edges).
  sel_.scene_requests.square_and_band = {sel_.origin - sel_.band_w, sel_.origin + (n - 1) + sel_.band_w};
  sel_.visible_blocks.clear();
  sel_.level0_hidden_clusters = sel_.level1_hidden_blocks = 0;
  if (!sel_.terrain_visible) {
    sel_.band_visible = false;
    // No Level0 is drawn either: the passes skip everything.
    return sel_;
  }
  cull(view, eye, paging);
  return sel_;
}

void TwoLevelSelector::cull(const TwoLevelView& view, const glm::dvec2& eye, const Level1Paging& paging) {
  const auto& hf = hf_;
  const int n = sel_.n;
  const glm::ivec2 origin = sel_.origin;
  const auto in_view = [&](const glm::dvec3& lo, const glm::dvec3& hi) {
    return view.box_in_view(lo - view.position, hi - view.position);
  };
  // Blocks and clusters behind nearer terrain are not drawn either, while
  // the eye is above what is drawn under it (the DEM, and Level0 when
  // Level1 does not hold the eye): lod/horizon_culling.h.
  const bool eye_in_square =
      eye.x >= origin.x && eye.y >= origin.y && eye.x <= origin.x + n - 1 && eye.y <= origin.y + n - 1;
  // Paged heights, live: no wait for the ground under the eye; not in yet,
  // no culling this frame.
  terrain::TileMisses misses;
  const bool no_wait = hf.paged && paging.no_wait;
  const bool over_ground = no_wait ? terrain::back_faces_hidden(hf.resident_only(misses), view.position)
                                   : terrain::back_faces_hidden(hf, view.position);
  const bool eye_above = over_ground && misses.count == 0 &&
                         (eye_in_square || view.position.z > level0_heights_.height_at(eye.x, eye.y));
  int hidden_count = 0;
  MarkHidden occlusion;
  if (horizon_ && eye_above)
    occlusion = [&](const std::vector<HorizonCulling::Box>& boxes, std::vector<std::uint8_t>& hidden) {
      hidden_count = horizon_->mark_hidden(view.position, view.earth_radius_m, 10.0 * view.near_m, boxes, hidden);
    };
  sel_.visible_blocks = visible_level1_blocks(hf, pyramid_, origin, n, level0_.max_error_m, in_view, eye, occlusion);
  sel_.level1_hidden_blocks = std::exchange(hidden_count, 0);
  const glm::ivec2 g0 = origin - sel_.band_w, g1 = origin + (n - 1) + sel_.band_w;
  const auto mm = rect_minmax(pyramid_, g0.x, g0.y, g1.x, g1.y);
  const glm::dvec3 band_lo =
      glm::dvec3(std::max(g0.x, 0) * hf.spacing_x_m, std::max(g0.y, 0) * hf.spacing_y_m, mm.lo) - view.position;
  const glm::dvec3 band_hi = glm::dvec3(std::min(g1.x, hf.width - 1) * hf.spacing_x_m,
                                        std::min(g1.y, hf.height - 1) * hf.spacing_y_m, mm.hi) - view.position;
  sel_.band_visible = view.box_in_view(band_lo, band_hi);
  // The band target is cleared, drawn and read only inside the band's screen rectangle.
  if (!options_.band_inline) sel_.band_rect = view.screen_rect(band_lo, band_hi);
  if (!sel_.visible_blocks.empty()) update_walls(view);
  // Level0: clusters of the static buffer outside the view are skipped whole;
  // inside the square nothing is drawn; outside it no discard, so the depth
  // test can reject hidden fragments early.
  BandRing ring;
  ring.lo = g0;
  ring.hi = g1;
  ring.eye = view.position;
  ring.spacing = {hf.spacing_x_m, hf.spacing_y_m};
  ring.tolerance_m = BandRing::tolerance_for(level0_.max_error_m);
  ring.earth_radius_m = view.earth_radius_m;
  const bool split = band_split_ && options_.band_inline;
  sel_.level0_runs[2].clear();
  clusters_->select(origin, origin + (n - 1), in_view, sel_.level0_runs[0], sel_.level0_runs[1], occlusion,
                    split ? &ring : nullptr, split ? &sel_.level0_runs[2] : nullptr);
  sel_.level0_hidden_clusters = hidden_count;
}

// The seam walls: each spans from the higher of (Level1 edge, Level0
// surface) down to a little below the lower one, so no sliver opens where
// Level0's surface bends between edge samples. Level0's height at an edge
// sample is a search of its triangles, so only the stretches of the edge
// that may be in view are filled: a stretch's box spans every height the
// DEM and Level0 take, and a wall of no height at the lowest of them lies
// inside it.
void TwoLevelSelector::update_walls(const TwoLevelView& view) {
  const auto& hf = hf_;
  const int n = sel_.n;
  const glm::ivec2 origin = sel_.origin;
  constexpr float kBelow = 1.0f;
  constexpr int q = kLevel1BlockQuads;  // n - 1 is a multiple of it: each stretch lies on one side
  if (walls_n_ != n || walls_origin_ != origin) {
    if (walls_n_ != n) perimeter_ = level1_perimeter(n);
    walls_n_ = n;
    walls_origin_ = origin;
    stretch_filled_.assign(perimeter_.size() / q, 0);
    sel_.wall_z.resize(perimeter_.size() * 2);
    std::fill(sel_.wall_z.begin(), sel_.wall_z.end(), glm::vec2(1.0f, float(terrain_z_lo_)));
    ++sel_.wall_version;
  }
  const size_t count = perimeter_.size();
  bool changed = false;
  for (size_t stretch = 0; stretch < stretch_filled_.size(); ++stretch) {
    if (stretch_filled_[stretch]) continue;
    const glm::ivec2 a = origin + perimeter_[stretch * q], b = origin + perimeter_[(stretch * q + q) % count];
    const glm::ivec2 lo = glm::min(a, b), hi = glm::max(a, b);
    const glm::dvec3 box_lo(lo.x * hf.spacing_x_m, lo.y * hf.spacing_y_m, terrain_z_lo_ - kBelow);
    const glm::dvec3 box_hi(hi.x * hf.spacing_x_m, hi.y * hf.spacing_y_m, terrain_z_hi_);
    if (!view.box_in_view(box_lo - view.position, box_hi - view.position)) continue;
    stretch_filled_[stretch] = 1;
    changed = true;
    int hint = -1;  // the stretch walks from sample to neighbouring sample
    for (size_t j = stretch * q; j <= stretch * q + q; ++j) {
      const size_t k = j % count;
      const glm::ivec2 s = origin + perimeter_[k];
      const float h1 = hf.at_clamped(s.x, s.y);
      const double h = level0_heights_.height_at(s.x, s.y, &hint);
      const float h0 = std::isfinite(h) ? float(h) : h1;
      sel_.wall_z[2 * k] = {1.0f, std::max(h0, h1)};
      sel_.wall_z[2 * k + 1] = {1.0f, std::min(h0, h1) - kBelow};
    }
  }
  if (changed) ++sel_.wall_version;
}

}  // namespace ig::lod
