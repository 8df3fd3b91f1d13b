#pragma once
// The quadtree of square chunks shared by Chunked LOD (Ulrich 2002) and
// CDLOD (Strugar 2010). Every node is a regular grid of kChunkQuads x
// kChunkQuads quads: the root spans the whole DEM at a stride of 2^depth
// samples per quad, each level halves the stride and the node's side, and
// the leaves are full resolution (stride 1, 32 x 32 samples). Per node: its
// height range (bounding box) and its geometric error, the largest vertical
// distance between a full-resolution sample in the node and the node's mesh.
//
// DEMs of any size: the tree covers the enclosing square of kChunkQuads *
// 2^depth quads; nodes that start past the DEM's last sample are not
// created, and vertices past the edge clamp onto it (as the shaders do), so
// edge nodes are folded, not padded with invented heights.

#include <array>
#include <vector>

#include <glm/vec3.hpp>

#include "lod/chunk_grid_error.h"
#include "terrain/heightfield.h"

namespace ig::lod {

constexpr int kChunkQuads = 32;

struct ChunkNode {
  int i0 = 0, j0 = 0;  // origin sample
  int level = 0;       // 0 = root
  int stride = 1;      // samples per quad
  int parent = -1;
  std::array<int, 4> children{-1, -1, -1, -1};  // south-west, south-east, north-west, north-east; -1: none
  HeightRange heights;
  float own_error_m = 0.0f;  // of this node's own mesh
  float error_m = 0.0f;      // max(own, children's error_m): never grows down the tree
  int triangles = 0;         // non-degenerate mesh triangles (clamped onto the DEM)
  std::array<int, 4> edge_segments{};  // non-degenerate segments per side (south, east, north, west)
  std::array<bool, 4> on_dem_edge{};   // side lies on the DEM's outer edge
  int size() const { return kChunkQuads * stride; }  // samples a side (before clamping)
  bool leaf() const { return children[0] < 0 && children[1] < 0 && children[2] < 0 && children[3] < 0; }
};

class ChunkQuadtree {
 public:
  explicit ChunkQuadtree(const terrain::Heightfield& hf);

  const terrain::Heightfield& heightfield() const { return hf_; }
  const std::vector<ChunkNode>& nodes() const { return nodes_; }
  const ChunkNode& node(int k) const { return nodes_[size_t(k)]; }
  int depth() const { return depth_; }  // levels 0 (root) .. depth (leaves)
  double build_ms() const { return build_ms_; }

  // The node's bounding box in terrain-local metres (clamped to the DEM).
  void box(const ChunkNode& n, glm::dvec3& lo, glm::dvec3& hi) const;
  // The box of quadrant q (child order) of node n.
  void quadrant_box(const ChunkNode& n, int q, glm::dvec3& lo, glm::dvec3& hi) const;

 private:
  const terrain::Heightfield& hf_;
  std::vector<ChunkNode> nodes_;  // breadth first: parents before children
  int depth_ = 0;
  double build_ms_ = 0.0;
};

// Euclidean distance from p to the box [lo, hi] (0 inside).
double box_distance(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi);
// Distance from p to the box's farthest corner.
double box_far_distance(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi);

}  // namespace ig::lod
