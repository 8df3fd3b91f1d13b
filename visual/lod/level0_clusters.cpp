#include "lod/level0_clusters.h"

#include <algorithm>
#include <utility>

#include <glm/common.hpp>

namespace ig::lod {

// Level0's triangles sorted by the Z-order (Morton) key of their centroid, so
// the triangles inside, across and outside any square form few runs.
Level0Mesh z_ordered(Level0Mesh mesh) {
  auto spread = [](std::uint32_t v) {
    std::uint64_t x = v & 0xFFFFu;
    x = (x | (x << 8)) & 0x00FF00FFu;
    x = (x | (x << 4)) & 0x0F0F0F0Fu;
    x = (x | (x << 2)) & 0x33333333u;
    x = (x | (x << 1)) & 0x55555555u;
    return x;
  };
  const size_t tris = mesh.indices.size() / 3;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> key(tris);
  for (size_t t = 0; t < tris; ++t) {
    glm::ivec2 sum(0);
    for (int k = 0; k < 3; ++k) sum += mesh.samples[mesh.indices[3 * t + k]];
    key[t] = {spread(std::uint32_t(sum.x / 3)) | (spread(std::uint32_t(sum.y / 3)) << 1), std::uint32_t(t)};
  }
  std::sort(key.begin(), key.end());
  std::vector<std::uint32_t> sorted;
  sorted.reserve(mesh.indices.size());
  for (const auto& [k, t] : key) sorted.insert(sorted.end(), {mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]});
  mesh.indices = std::move(sorted);
  return mesh;
}

void IndexRuns::append(std::uint32_t first_index, std::uint32_t index_count) {
  if (!first.empty() && first.back() + count.back() == first_index) {
    count.back() += index_count;
    return;
  }
  first.push_back(first_index);
  count.push_back(index_count);
}

std::uint64_t IndexRuns::indices() const {
  std::uint64_t n = 0;
  for (auto c : count) n += c;
  return n;
}

Level0Clusters::Level0Clusters(const Level0Mesh& mesh, glm::dvec2 spacing_m, int triangles_per_cluster)
    : mesh_(mesh), spacing_(spacing_m) {
  const auto triangles = std::uint32_t(mesh.indices.size() / 3);
  const auto per = std::uint32_t(std::max(triangles_per_cluster, 1));
  for (std::uint32_t t0 = 0; t0 < triangles; t0 += per) {
    Cluster c{t0, std::min(per, triangles - t0), glm::ivec2(1 << 30), glm::ivec2(-(1 << 30)), 1e30f, -1e30f};
    for (std::uint32_t k = 3 * t0; k < 3 * (t0 + c.triangles); ++k) {
      const auto v = mesh.indices[k];
      c.lo = glm::min(c.lo, mesh.samples[v]);
      c.hi = glm::max(c.hi, mesh.samples[v]);
      c.z_lo = std::min(c.z_lo, mesh.positions[v].z);
      c.z_hi = std::max(c.z_hi, mesh.positions[v].z);
    }
    clusters_.push_back(c);
  }
  for (std::uint32_t k0 = 0; k0 < clusters_.size(); k0 += kClustersPerGroup) {
    Group g{k0, std::min<std::uint32_t>(kClustersPerGroup, std::uint32_t(clusters_.size()) - k0), glm::ivec2(1 << 30),
            glm::ivec2(-(1 << 30)), 1e30f, -1e30f};
    for (std::uint32_t k = k0; k < k0 + g.clusters; ++k) {
      g.lo = glm::min(g.lo, clusters_[k].lo);
      g.hi = glm::max(g.hi, clusters_[k].hi);
      g.z_lo = std::min(g.z_lo, clusters_[k].z_lo);
      g.z_hi = std::max(g.z_hi, clusters_[k].z_hi);
    }
    groups_.push_back(g);
  }
}

int Level0Clusters::select(glm::ivec2 square_lo, glm::ivec2 square_hi, const BoxVisible& visible, IndexRuns& outside,
                           IndexRuns& crossing, const MarkHidden& mark_hidden, const BandRing* ring,
                           IndexRuns* clear_of_band) const {
  outside.clear();
  crossing.clear();
  if (clear_of_band) clear_of_band->clear();
  auto inside_square = [&](glm::ivec2 lo, glm::ivec2 hi) {
    return lo.x >= square_lo.x && lo.y >= square_lo.y && hi.x <= square_hi.x && hi.y <= square_hi.y;
  };
  auto clear_of_square = [&](glm::ivec2 lo, glm::ivec2 hi) {
    return hi.x <= square_lo.x || lo.x >= square_hi.x || hi.y <= square_lo.y || lo.y >= square_hi.y;
  };
  if (square_lo != split_lo_ || square_hi != split_hi_) {
    split_lo_ = square_lo;
    split_hi_ = square_hi;
    split_first_.assign(clusters_.size(), kNotSplit);
    split_count_.assign(clusters_.size(), 0);
    pieces_.clear();
  }
  int culled = 0;
  in_view_.clear();
  boxes_.clear();
  auto box_of = [&](const auto& c) {
    return HorizonCulling::Box{glm::dvec3(c.lo.x * spacing_.x, c.lo.y * spacing_.y, c.z_lo),
                               glm::dvec3(c.hi.x * spacing_.x, c.hi.y * spacing_.y, c.z_hi)};
  };
  // A group out of view has every cluster out of view (their boxes lie in
  // its box): one test for most of a whole-DEM mesh at a narrow field of view.
  for (const Group& g : groups_) {
    if (inside_square(g.lo, g.hi)) continue;
    const HorizonCulling::Box group_box = box_of(g);
    const bool group_visible = visible(group_box.lo, group_box.hi);
    for (std::uint32_t k = g.first_cluster; k < g.first_cluster + g.clusters; ++k) {
      const Cluster& c = clusters_[k];
      if (inside_square(c.lo, c.hi)) continue;
      const HorizonCulling::Box b = box_of(c);
      if (!group_visible || !visible(b.lo, b.hi)) {
        ++culled;
        continue;
      }
      in_view_.push_back(k);
      boxes_.push_back(b);
    }
  }
  hidden_.assign(in_view_.size(), 0);
  if (mark_hidden) mark_hidden(boxes_, hidden_);
  for (size_t v = 0; v < in_view_.size(); ++v) {
    const Cluster& c = clusters_[in_view_[v]];
    if (hidden_[v]) {
      ++culled;
      continue;
    }
    if (clear_of_square(c.lo, c.hi)) {
      const bool band_free = ring && clear_of_band && !ring->may_reach(c.lo, c.hi, c.z_lo, c.z_hi);
      (band_free ? *clear_of_band : outside).append(3 * c.first_triangle, 3 * c.triangles);
      continue;
    }
    const std::uint32_t k = in_view_[v];
    if (split_first_[k] == kNotSplit) split_crossing(k, square_lo, square_hi);
    for (std::uint32_t p = split_first_[k]; p < split_first_[k] + split_count_[k]; ++p)
      (pieces_[p].crossing ? crossing : outside).append(pieces_[p].first_index, pieces_[p].index_count);
  }
  return culled;
}

// A crossing cluster's triangles as runs of consecutive triangles of one
// kind (wholly outside the square, or across its edge); those inside it are
// left out. Appended in order, the runs merge as the triangles would.
void Level0Clusters::split_crossing(std::uint32_t k, glm::ivec2 square_lo, glm::ivec2 square_hi) const {
  const Cluster& c = clusters_[k];
  split_first_[k] = std::uint32_t(pieces_.size());
  for (std::uint32_t t = c.first_triangle; t < c.first_triangle + c.triangles; ++t) {
    const auto* idx = &mesh_.indices[3 * t];
    const glm::ivec2 a = mesh_.samples[idx[0]], b = mesh_.samples[idx[1]], d = mesh_.samples[idx[2]];
    const glm::ivec2 mn = glm::min(a, glm::min(b, d)), mx = glm::max(a, glm::max(b, d));
    if (mn.x >= square_lo.x && mn.y >= square_lo.y && mx.x <= square_hi.x && mx.y <= square_hi.y) continue;
    const bool across = !(mx.x <= square_lo.x || mn.x >= square_hi.x || mx.y <= square_lo.y || mn.y >= square_hi.y);
    if (pieces_.size() > split_first_[k]) {
      Piece& last = pieces_.back();
      if (last.crossing == across && last.first_index + last.index_count == 3 * t) {
        last.index_count += 3;
        continue;
      }
    }
    pieces_.push_back({3 * t, 3, across});
  }
  split_count_[k] = std::uint32_t(pieces_.size()) - split_first_[k];
}

}  // namespace ig::lod
