#include "lod/chunk_quadtree.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace ig::lod {
namespace {

// Segments of a node side (kChunkQuads at `stride` from `first`) that keep a
// non-zero length once clamped onto a DEM `samples` wide.
int edge_segment_count(int first, int stride, int samples) {
  int c = 0;
  for (int q = 0; q < kChunkQuads; ++q)
    c += std::min(first + (q + 1) * stride, samples - 1) > std::min(first + q * stride, samples - 1);
  return c;
}

}  // namespace

ChunkQuadtree::ChunkQuadtree(const terrain::Heightfield& hf) : hf_(hf) {
  const auto t0 = std::chrono::steady_clock::now();
  const int span = std::max(1, std::max(hf.width, hf.height) - 1);
  while ((kChunkQuads << depth_) < span) ++depth_;

  ChunkNode root;
  root.stride = 1 << depth_;
  nodes_.push_back(root);
  for (size_t k = 0; k < nodes_.size(); ++k) {
    ChunkNode n = nodes_[k];  // a copy: push_back below may move nodes_
    const int size = n.size();
    if (n.stride == 1) n.heights = sample_height_range(hf, n.i0, n.j0, size, size);  // inner nodes: from their children
    n.own_error_m = grid_max_error(hf, n.i0, n.j0, kChunkQuads, n.stride);
    n.triangles = grid_triangle_count(hf, n.i0, n.j0, kChunkQuads, n.stride);
    const int segs_x = edge_segment_count(n.i0, n.stride, hf.width);
    const int segs_y = edge_segment_count(n.j0, n.stride, hf.height);
    n.edge_segments = {segs_x, segs_y, segs_x, segs_y};
    n.on_dem_edge = {n.j0 == 0, n.i0 + size >= hf.width - 1, n.j0 + size >= hf.height - 1, n.i0 == 0};
    if (n.stride > 1) {
      const int half = size / 2;
      for (int q = 0; q < 4; ++q) {
        ChunkNode c;
        c.i0 = n.i0 + (q & 1) * half;
        c.j0 = n.j0 + (q >> 1) * half;
        if (c.i0 >= hf.width - 1 || c.j0 >= hf.height - 1) continue;  // wholly past the DEM
        c.level = n.level + 1;
        c.stride = n.stride / 2;
        c.parent = int(k);
        n.children[q] = int(nodes_.size());
        nodes_.push_back(c);
      }
    }
    nodes_[k] = n;
  }
  // Children first (they come after their parents): monotone errors, and
  // inner nodes' height ranges as the union of their children's (which
  // cover every DEM sample of the parent).
  for (size_t k = nodes_.size(); k-- > 0;) {
    ChunkNode& n = nodes_[k];
    n.error_m = n.own_error_m;
    bool first = true;
    for (int c : n.children) {
      if (c < 0) continue;
      const ChunkNode& child = nodes_[size_t(c)];
      n.error_m = std::max(n.error_m, child.error_m);
      n.heights.min_m = first ? child.heights.min_m : std::min(n.heights.min_m, child.heights.min_m);
      n.heights.max_m = first ? child.heights.max_m : std::max(n.heights.max_m, child.heights.max_m);
      first = false;
    }
  }
  build_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void ChunkQuadtree::box(const ChunkNode& n, glm::dvec3& lo, glm::dvec3& hi) const {
  const int i1 = std::min(n.i0 + n.size(), hf_.width - 1), j1 = std::min(n.j0 + n.size(), hf_.height - 1);
  lo = glm::dvec3(n.i0 * hf_.spacing_x_m, n.j0 * hf_.spacing_y_m, n.heights.min_m);
  hi = glm::dvec3(i1 * hf_.spacing_x_m, j1 * hf_.spacing_y_m, n.heights.max_m);
}

void ChunkQuadtree::quadrant_box(const ChunkNode& n, int q, glm::dvec3& lo, glm::dvec3& hi) const {
  if (n.children[q] >= 0) return box(nodes_[size_t(n.children[q])], lo, hi);
  // A leaf has no quadrants of its own; its box is the best bound.
  box(n, lo, hi);
}

double box_distance(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi) {
  const glm::dvec3 d(std::max({lo.x - p.x, 0.0, p.x - hi.x}), std::max({lo.y - p.y, 0.0, p.y - hi.y}),
                     std::max({lo.z - p.z, 0.0, p.z - hi.z}));
  return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

double box_far_distance(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi) {
  const glm::dvec3 d(std::max(std::abs(p.x - lo.x), std::abs(p.x - hi.x)),
                     std::max(std::abs(p.y - lo.y), std::abs(p.y - hi.y)),
                     std::max(std::abs(p.z - lo.z), std::abs(p.z - hi.z)));
  return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

}  // namespace ig::lod
