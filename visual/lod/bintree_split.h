#pragma once
// The split both ROAM meshes share (lod/roam_tessellator.h, the per-frame
// mesh; lod/roam_level0_mesh.h, Level0's): a bintree triangle splits at its
// base midpoint into two children, and when its base neighbour is coarser
// that neighbour is split first (a forced split), so the two always split
// together as a diamond and the mesh never cracks (Duchaineau et al.,
// "ROAMing Terrain", 1997).
//
// Tri needs v[3] (apex, left, right: counter-clockwise, the base runs left ->
// right), base, left and right (the neighbours' ids, -1 for none) and child
// (the first of two consecutive children, -1 for a leaf). No GL here.

#include <type_traits>
#include <vector>

#include <glm/vec2.hpp>

namespace ig::lod::bintree {

// Points the neighbour link of t that names `from` at `to`.
template <class Tri>
void replace_link(Tri& t, int from, int to) {
  if (t.base == from) t.base = to;
  else if (t.left == from) t.left = to;
  else if (t.right == from) t.right = to;
}

// Appends the two children of x, (mid, apex, left) and (mid, right, apex),
// and links them to x's outside neighbours; the links across x's base are
// the caller's. Returns the first child.
template <class Tri>
int make_children(std::vector<Tri>& tris, int x) {
  const Tri t = tris[x];
  using Vertex = std::remove_cvref_t<decltype(t.v[0])>;
  const Vertex m((glm::ivec2(t.v[1]) + glm::ivec2(t.v[2])) / 2);
  const int c0 = int(tris.size()), c1 = c0 + 1;
  Tri a{}, b{};
  a.v[0] = m, a.v[1] = t.v[0], a.v[2] = t.v[1];
  b.v[0] = m, b.v[1] = t.v[2], b.v[2] = t.v[0];
  a.base = t.left;
  b.base = t.right;
  a.left = c1;
  b.right = c0;
  tris.push_back(a);
  tris.push_back(b);
  tris[x].child = c0;
  if (t.left >= 0) replace_link(tris[t.left], x, c0);
  if (t.right >= 0) replace_link(tris[t.right], x, c1);
  return c0;
}

// Splits x (nothing when it is split already) with its base neighbour y,
// forcing y's split first when y is coarser. Hooks, called for x and for
// every forced split on the way:
//   on_split(forced)     before the children are made;
//   on_children(p, c0)   after triangle p got children c0, c0 + 1;
//   on_done(x, y)        after the diamond is linked (y = -1 at the border).
template <class Tri, class OnSplit, class OnChildren, class OnDone>
void split(std::vector<Tri>& tris, int x, bool forced, const OnSplit& on_split, const OnChildren& on_children,
           const OnDone& on_done) {
  if (tris[x].child >= 0) return;
  int y = tris[x].base;
  if (y >= 0 && tris[y].base != x) {
    split(tris, y, true, on_split, on_children, on_done);  // afterwards x's base neighbour is y's child facing x
    y = tris[x].base;
  }
  on_split(forced);
  const int x0 = make_children(tris, x), x1 = x0 + 1;
  on_children(x, x0);
  if (y >= 0) {
    const int y0 = make_children(tris, y), y1 = y0 + 1;
    on_children(y, y0);
    tris[x0].right = y1;
    tris[x1].left = y0;
    tris[y0].right = x1;
    tris[y1].left = x0;
  }
  on_done(x, y);
}

}  // namespace ig::lod::bintree
