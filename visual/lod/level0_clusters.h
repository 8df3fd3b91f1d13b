#pragma once
// Level0's static index buffer, in Z order, cut into clusters of consecutive
// triangles, each with a box. Per frame the clusters are culled against the
// view and classified against Level1's square, so the draw is a few runs of
// the static buffer: the paper draws all of Level0 every frame, but seen at
// FOV 15 most of a whole-DEM mesh is outside the view, and its vertices cost
// shading time on any GPU. No GL here: the runs are offsets into the buffer.

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "lod/band_ring.h"
#include "lod/horizon_culling.h"
#include "lod/roam_level0_mesh.h"

namespace ig::lod {

// The mesh with its triangles sorted by the Z-order (Morton) key of their
// centroid, so the triangles of any square form few runs and clusters are compact.
Level0Mesh z_ordered(Level0Mesh mesh);

// Runs of the index buffer: first index and index count of each.
struct IndexRuns {
  std::vector<std::uint32_t> first, count;
  void clear() {
    first.clear();
    count.clear();
  }
  void append(std::uint32_t first_index, std::uint32_t index_count);  // merges with the last run when contiguous
  std::uint64_t indices() const;
};

class Level0Clusters {
 public:
  // `mesh` must outlive this object (its triangles are read per frame).
  Level0Clusters(const Level0Mesh& mesh, glm::dvec2 spacing_m, int triangles_per_cluster = 128);

  // Boxes in terrain-local metres (x, y) and height (z), as the heights are drawn.
  using BoxVisible = std::function<bool(const glm::dvec3& lo, const glm::dvec3& hi)>;

  // Level0's triangles for one frame, given Level1's square [lo, hi] in
  // samples: `outside` wholly outside it, `crossing` across its edge (the
  // discarding program), triangles inside it never. Clusters whose box is not
  // visible, or that `mark_hidden` marks, are skipped whole. Returns the
  // number of clusters culled (out of view or hidden). With `ring` and
  // `clear_of_band`, clusters outside the square that the band cannot reach
  // (BandRing::may_reach) go to `clear_of_band` instead of `outside`.
  int select(glm::ivec2 square_lo, glm::ivec2 square_hi, const BoxVisible& visible, IndexRuns& outside,
             IndexRuns& crossing, const MarkHidden& mark_hidden = {}, const BandRing* ring = nullptr,
             IndexRuns* clear_of_band = nullptr) const;

  int cluster_count() const { return int(clusters_.size()); }

 private:
  struct Cluster {
    std::uint32_t first_triangle, triangles;
    glm::ivec2 lo, hi;  // samples
    float z_lo, z_hi;
  };
  // Consecutive clusters (neighbours in Z order) under one box.
  struct Group {
    std::uint32_t first_cluster, clusters;
    glm::ivec2 lo, hi;
    float z_lo, z_hi;
  };
  static constexpr std::uint32_t kClustersPerGroup = 16;
  const Level0Mesh& mesh_;
  glm::dvec2 spacing_;
  std::vector<Cluster> clusters_;
  std::vector<Group> groups_;
  // The runs of each cluster that crosses Level1's square, kept while the
  // square stays put (Level1 moves in whole samples, the view every frame).
  struct Piece {
    std::uint32_t first_index, index_count;
    bool crossing;  // across the square's edge; else wholly outside it
  };
  void split_crossing(std::uint32_t k, glm::ivec2 square_lo, glm::ivec2 square_hi) const;
  static constexpr std::uint32_t kNotSplit = ~0u;
  mutable glm::ivec2 split_lo_{0}, split_hi_{-1};
  mutable std::vector<std::uint32_t> split_first_, split_count_;  // per cluster: its pieces in pieces_
  mutable std::vector<Piece> pieces_;
  // Per-frame scratch: clusters in view and their boxes.
  mutable std::vector<std::uint32_t> in_view_;
  mutable std::vector<HorizonCulling::Box> boxes_;
  mutable std::vector<std::uint8_t> hidden_;
};

}  // namespace ig::lod
