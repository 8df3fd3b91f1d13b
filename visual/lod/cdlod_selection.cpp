#include "lod/cdlod_selection.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ig::lod {

double CdlodRanges::range(int lod) const {
  return lod >= top_lod ? std::numeric_limits<double>::infinity() : std::ldexp(lod0_range_m, lod);
}
double CdlodRanges::morph_end(int lod) const { return kMorphEndRatio * range(lod); }
double CdlodRanges::morph_start(int lod) const { return morph_start_ratio * morph_end(lod); }
double CdlodRanges::morph(int lod, double d) const {
  if (lod >= top_lod) return 0.0;
  const double a = morph_start(lod), b = morph_end(lod);
  return std::clamp((d - a) / (b - a), 0.0, 1.0);
}

namespace {

struct Walk {
  const ChunkQuadtree& tree;
  const CdlodRanges& ranges;
  glm::dvec3 eye;
  const BoxVisible& visible;
  std::vector<CdlodArea> out;

  // Strugar's LODSelect: false when the node lies wholly beyond its own
  // range (the caller draws that quarter at its coarser LOD).
  bool select(int k) {
    const ChunkNode& n = tree.node(k);
    const int lod = tree.depth() - n.level;
    glm::dvec3 lo, hi;
    tree.box(n, lo, hi);
    const double d = box_distance(eye, lo, hi);
    if (d > ranges.range(lod)) return false;
    if (!visible(lo, hi)) return true;
    if (lod == 0 || n.leaf() || d > ranges.range(lod - 1)) {
      out.push_back({k, -1, lod});
      return true;
    }
    for (int q = 0; q < 4; ++q) {
      const int c = n.children[q];
      if (c < 0 || select(c)) continue;
      tree.quadrant_box(n, q, lo, hi);
      if (visible(lo, hi)) out.push_back({k, q, lod});
    }
    return true;
  }
};

}  // namespace

std::vector<CdlodArea> cdlod_select(const ChunkQuadtree& tree, const CdlodRanges& ranges, const glm::dvec3& eye,
                                    const BoxVisible& visible) {
  Walk w{tree, ranges, eye, visible, {}};
  w.select(0);  // the root's range is infinite: it always answers
  return std::move(w.out);
}

glm::dvec3 cdlod_vertex(const terrain::Heightfield& hf, const CdlodRanges& ranges, glm::ivec2 p, int lod,
                        const glm::dvec3& eye) {
  auto clamped = [&](glm::ivec2 s) {
    return glm::ivec2(std::clamp(s.x, 0, hf.width - 1), std::clamp(s.y, 0, hf.height - 1));
  };
  auto position = [&](glm::ivec2 s) {
    const glm::ivec2 c = clamped(s);
    return glm::dvec3(c.x, c.y, hf.at(c.x, c.y));
  };
  auto distance = [&](const glm::dvec3& v) {
    const glm::dvec3 rel(v.x * hf.spacing_x_m - eye.x, v.y * hf.spacing_y_m - eye.y, v.z - eye.z);
    return std::sqrt(rel.x * rel.x + rel.y * rel.y + rel.z * rel.z);
  };
  glm::dvec3 v = position(p);
  for (int l = lod; l < ranges.top_lod; ++l) {
    const double m = ranges.morph(l, distance(v));
    if (m <= 0.0) break;
    const glm::ivec2 odd((p.x >> l) & 1, (p.y >> l) & 1);
    const glm::ivec2 target = p - odd * (1 << l);
    if (m >= 1.0) {
      p = target;
      v = position(p);
      continue;
    }
    const glm::dvec3 t = position(target);
    return v + (t - v) * m;
  }
  return v;
}

}  // namespace ig::lod
