#include "lod/geomipmap_blocks.h"

#include <algorithm>
#include <chrono>

namespace ig::lod {

bool GeoMipConfig::stitched() const {
  for (int s : side_level)
    if (s != level) return true;
  return false;
}

std::uint32_t GeoMipConfig::key() const {
  std::uint32_t k = std::uint32_t(level);
  for (int s : side_level) k = k * 8 + std::uint32_t(s);
  return k;
}

namespace {

constexpr int N = kGeoMipBlockQuads;

// Position of a point `t` along a side, `depth` into the block.
glm::ivec2 side_point(int side, int t, int depth) {
  switch (side) {
    case kSouth: return {t, depth};
    case kEast: return {N - depth, t};
    case kNorth: return {t, N - depth};
    default: return {depth, t};  // west
  }
}
// The sides at a side's t = 0 and t = N ends.
int side_at_start(int side) { return side == kSouth || side == kNorth ? kWest : kSouth; }
int side_at_end(int side) { return side == kSouth || side == kNorth ? kEast : kNorth; }

void push_ccw(std::vector<glm::ivec2>& out, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
  const long long area2 = (long long)(b.x - a.x) * (c.y - a.y) - (long long)(b.y - a.y) * (c.x - a.x);
  if (area2 == 0) return;
  if (area2 < 0) std::swap(b, c);
  out.insert(out.end(), {a, b, c});
}

}  // namespace

std::vector<glm::ivec2> geomipmap_triangles(const GeoMipConfig& c) {
  std::vector<glm::ivec2> out;
  const int s = 1 << c.level, n = N / s;
  if (n == 1) {  // the coarsest level: one quad, nothing can be coarser next to it
    out = {{0, 0}, {N, 0}, {N, N}, {0, 0}, {N, N}, {0, N}};
    return out;
  }
  std::array<bool, 4> st{};
  for (int k = 0; k < 4; ++k) st[size_t(k)] = c.side_level[size_t(k)] > c.level;
  // Plain quads: those in no stitched side's row.
  for (int qj = 0; qj < n; ++qj)
    for (int qi = 0; qi < n; ++qi) {
      if ((st[kSouth] && qj == 0) || (st[kNorth] && qj == n - 1) || (st[kWest] && qi == 0) ||
          (st[kEast] && qi == n - 1))
        continue;
      const glm::ivec2 p(qi * s, qj * s);
      out.insert(out.end(), {p, p + glm::ivec2(s, 0), p + glm::ivec2(s, s), p, p + glm::ivec2(s, s), p + glm::ivec2(0, s)});
    }
  for (int side = 0; side < 4; ++side) {
    const auto strip = geomipmap_strip_triangles(c, side);
    out.insert(out.end(), strip.begin(), strip.end());
  }
  return out;
}

std::vector<glm::ivec2> geomipmap_strip_triangles(const GeoMipConfig& c, int side) {
  std::vector<glm::ivec2> out;
  const int s = 1 << c.level;
  if (c.side_level[size_t(side)] <= c.level || s >= N) return out;
  // The coarse edge (stride S) zipped to the first inner row (stride s); the
  // inner row stops one quad short of an end whose adjacent side is stitched
  // too (the corner quad is split along its diagonal between the two strips).
  const int S = 1 << c.side_level[size_t(side)];
  const int t0 = c.side_level[size_t(side_at_start(side))] > c.level ? s : 0;
  const int t1 = c.side_level[size_t(side_at_end(side))] > c.level ? N - s : N;
  std::vector<int> outer, inner;
  for (int t = 0; t <= N; t += S) outer.push_back(t);
  for (int t = t0; t <= t1; t += s) inner.push_back(t);
  size_t i = 0, j = 0;
  while (i + 1 < outer.size() || j + 1 < inner.size()) {
    const bool advance_outer = j + 1 >= inner.size() || (i + 1 < outer.size() && outer[i + 1] <= inner[j + 1]);
    if (advance_outer) {
      push_ccw(out, side_point(side, outer[i], 0), side_point(side, outer[i + 1], 0), side_point(side, inner[j], s));
      ++i;
    } else {
      push_ccw(out, side_point(side, outer[i], 0), side_point(side, inner[j + 1], s), side_point(side, inner[j], s));
      ++j;
    }
  }
  return out;
}

GeoMipMapBlocks::GeoMipMapBlocks(const terrain::Heightfield& hf) : hf_(hf) {
  const auto t0 = std::chrono::steady_clock::now();
  blocks_x_ = std::max(1, (hf.width - 1 + N - 1) / N);
  blocks_y_ = std::max(1, (hf.height - 1 + N - 1) / N);
  blocks_.resize(size_t(blocks_x_) * blocks_y_);
  for (int by = 0; by < blocks_y_; ++by)
    for (int bx = 0; bx < blocks_x_; ++bx) {
      GeoMipBlock& b = blocks_[size_t(by) * blocks_x_ + bx];
      b.i0 = bx * N;
      b.j0 = by * N;
      b.heights = sample_height_range(hf, b.i0, b.j0, N, N);
      for (int l = 0; l < kGeoMipLevels; ++l) {
        b.error[l] = grid_max_error(hf, b.i0, b.j0, N >> l, 1 << l);
        b.triangles[l] = grid_triangle_count(hf, b.i0, b.j0, N >> l, 1 << l);
      }
    }
  build_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

GeoMipMapBlocks::Stats GeoMipMapBlocks::stats(int bx, int by, const GeoMipConfig& c) const {
  const GeoMipBlock& b = block(bx, by);
  if (!c.stitched()) return {b.error[size_t(c.level)], b.triangles[size_t(c.level)]};
  Stats s{b.error[size_t(c.level)], 0};
  for (int side = 0; side < 4; ++side) s.error_m = std::max(s.error_m, strip_error(bx, by, c, side));
  auto tri = triangles_cache_.find(c.key());
  if (tri == triangles_cache_.end()) tri = triangles_cache_.emplace(c.key(), geomipmap_triangles(c)).first;
  if (b.i0 + N <= hf_.width - 1 && b.j0 + N <= hf_.height - 1) {
    s.triangles = int(tri->second.size() / 3);  // nothing folded onto the DEM's edge
    return s;
  }
  const std::uint64_t key = (std::uint64_t(size_t(by) * blocks_x_ + bx) << 16) | c.key();
  auto it = stitched_triangles_.find(key);
  if (it == stitched_triangles_.end())
    it = stitched_triangles_.emplace(key, triangles_nondegenerate_count(hf_, b.i0, b.j0, tri->second)).first;
  s.triangles = it->second;
  return s;
}

float GeoMipMapBlocks::strip_error(int bx, int by, const GeoMipConfig& c, int side) const {
  if (c.side_level[size_t(side)] <= c.level) return 0.0f;
  // A strip depends on the level, its side's level and whether its two
  // adjacent sides are stitched.
  const int start = c.side_level[size_t(side_at_start(side))] > c.level;
  const int end = c.side_level[size_t(side_at_end(side))] > c.level;
  const std::uint64_t strip_key = ((std::uint64_t(c.level) * 8 + std::uint64_t(c.side_level[size_t(side)])) * 4 +
                                   std::uint64_t(side)) * 4 + std::uint64_t(start * 2 + end);
  const std::uint64_t key = (std::uint64_t(size_t(by) * blocks_x_ + bx) << 16) | strip_key;
  auto it = strip_errors_.find(key);
  if (it != strip_errors_.end()) return it->second;
  const GeoMipBlock& b = block(bx, by);
  const float e = triangles_max_error(hf_, b.i0, b.j0, geomipmap_strip_triangles(c, side));
  strip_errors_.emplace(key, e);
  return e;
}

GeoMipConfig GeoMipMapBlocks::config_of(int bx, int by, const std::vector<int>& levels) const {
  GeoMipConfig c;
  c.level = levels[size_t(by) * blocks_x_ + bx];
  auto level_at = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= blocks_x_ || y >= blocks_y_) return c.level;
    return std::max(c.level, levels[size_t(y) * blocks_x_ + x]);
  };
  c.side_level[kSouth] = level_at(bx, by - 1);
  c.side_level[kEast] = level_at(bx + 1, by);
  c.side_level[kNorth] = level_at(bx, by + 1);
  c.side_level[kWest] = level_at(bx - 1, by);
  return c;
}

int geomipmap_select_level(const std::array<float, kGeoMipLevels>& error, double distance_m,
                           double min_distance_m, double pixels_per_radian, double tau_px) {
  const double d = std::max(distance_m, min_distance_m);
  for (int l = kGeoMipLevels - 1; l > 0; --l)
    if (error[l] / d * pixels_per_radian <= tau_px) return l;
  return 0;
}

}  // namespace ig::lod
