// The pyramid ray cast (cast_ray, terrain/ray_cast.h; docs/ray-cast.md): a
// front-to-back traversal of the min/max pyramid, flat or curved. The shared
// watertight arithmetic is in terrain/ray_cast_kernel.h.
#include "terrain/ray_cast_kernel.h"

#include <stdexcept>

namespace ig::terrain {

using namespace ray_kernel;

namespace {

// The traversal, flat or curved (r.curve).
std::optional<RayHit> cast_ray_impl(const Heightfield& hf, const HeightPyramid& pyr, glm::dvec3 origin,
                                    glm::dvec3 dir, double max_t, const Curvature& curvature, RayCastStats& stats);

}  // namespace

std::optional<RayHit> cast_ray(const Heightfield& hf, const HeightPyramid& pyr, glm::dvec3 origin,
                               glm::dvec3 dir, double max_t) {
  RayCastStats unused;
  return cast_ray(hf, pyr, origin, dir, max_t, unused);
}

std::optional<RayHit> cast_ray(const Heightfield& hf, const HeightPyramid& pyr, glm::dvec3 origin,
                               glm::dvec3 dir, double max_t, RayCastStats& stats) {
  return cast_ray_impl(hf, pyr, origin, dir, max_t, Curvature{}, stats);
}

std::optional<RayHit> cast_ray(const Heightfield& hf, const HeightPyramid& pyr, glm::dvec3 origin,
                               glm::dvec3 dir, double max_t, const Curvature& curvature) {
  RayCastStats unused;
  return cast_ray_impl(hf, pyr, origin, dir, max_t, curvature, unused);
}

namespace {

std::optional<RayHit> cast_ray_impl(const Heightfield& hf, const HeightPyramid& pyr, glm::dvec3 origin,
                                    glm::dvec3 dir, double max_t, const Curvature& curvature, RayCastStats& stats) {
  stats = RayCastStats{};
  if (hf.width < 2 || hf.height < 2 || !valid_spacing(hf)) return std::nullopt;
  if (pyr.empty() || pyr.cells_x() != hf.width - 1 || pyr.cells_y() != hf.height - 1 || !hf.has_samples())
    throw std::invalid_argument("cast_ray: HeightPyramid was not built from this heightfield");
  const HeightPyramid::MinMax root = pyr.root();
  Ray r;
  if (!make_ray(origin, dir, max_t, scene_scale(hf, root.lo, root.hi), r)) return std::nullopt;
  if (curvature.radius_m > 0.0 && std::isfinite(curvature.radius_m) && std::isfinite(curvature.centre_x) &&
      std::isfinite(curvature.centre_y)) {
    r.curve = curvature;
    if (curvature.radius_m >= 1.0 && curvature.radius_m <= 1e100) {
      r.half_inv_r = 0.5 / curvature.radius_m;
      r.inv_r2 = 1.0 / (curvature.radius_m * curvature.radius_m);
    }
  }

  const double sx = hf.spacing_x_m, sy = hf.spacing_y_m;
  const std::int64_t ncx = pyr.cells_x(), ncy = pyr.cells_y();
  const double ext_x = double(ncx) * sx, ext_y = double(ncy) * sy;
  // Node size per level in metres. (c * 2^k) * s rounds exactly like
  // double(c << k) * s, so node edges coincide bit for bit with the vertex
  // coordinates i * s used by the triangle test.
  double node_w[40], node_h[40];
  node_w[0] = sx;
  node_h[0] = sy;
  for (int k = 1; k < pyr.num_levels(); ++k) {  // doubling is exact
    node_w[k] = node_w[k - 1] * 2;
    node_h[k] = node_h[k - 1] * 2;
  }

  // Why the first hit found is the nearest one (front-to-back order):
  // siblings' footprints are closed rectangles with disjoint interiors, and
  // a line meets each convex footprint in one interval of t, so those
  // intervals follow one another along the ray. Children are pushed so they
  // pop in increasing order of footprint entry t, and the traversal is depth
  // first, so every leaf under an earlier sibling is finished before any
  // leaf under a later one. Every surface point inside a footprint lies
  // within that footprint's interval, so a hit in an earlier subtree has t <=
  // that subtree's exit <= the entry of everything still on the stack: no
  // later node can contain a nearer hit, and the traversal ends. The only
  // exceptions are ties on shared boundaries (ray through a node corner or
  // running along a node edge, vertical rays) and rounding; for those the
  // loop keeps popping but discards any node whose conservative entry t
  // exceeds the best hit, which costs one comparison per stacked node and
  // keeps the result exact whatever the order.
  struct Entry {
    double key;  // conservative 3D entry t
    int level, i, j;
  };
  Entry stack[4 * 40];  // <= 3 siblings left per level + 1; levels <= 32
  int sp = 0;
  double best = max_t;
  bool found = false;
  int hit_i = -1, hit_j = -1;

  {
    double t2d, key;
    ++stats.nodes_tested;
    double lo = root.lo, hi = root.hi;
    drawn_range(r, 0.0, double(ncx) * sx, 0.0, double(ncy) * sy, lo, hi);
    if (!box_test(r, 0.0, double(ncx) * sx, 0.0, double(ncy) * sy, lo, hi, best, t2d, key))
      return std::nullopt;
    stack[sp++] = Entry{key, pyr.num_levels() - 1, 0, 0};
  }

  // The nearest child is visited next without a trip through the stack
  // (a store just made and read back at once stalls the load).
  Entry e{};
  bool have_next = false;
  while (have_next || sp > 0) {
    if (!have_next) e = stack[--sp];
    have_next = false;
    if (e.key > best) continue;
    if (e.level == 0) {
      ++stats.cells_tested;
      // A cell whose box contains the origin (entry t <= 0): an origin on
      // its surface is a hit at t = 0 (see origin_on_surface).
      if (e.key <= 0 && origin_on_cell_surface(hf, r, e.i, e.j)) {
        best = 0;
        found = true;
        hit_i = e.i;
        hit_j = e.j;
        continue;
      }
      if (intersect_cell(hf, r, e.i, e.j, best)) {
        found = true;
        hit_i = e.i;
        hit_j = e.j;
      }
      continue;
    }
    const int cl = e.level - 1;
    const int cw = pyr.level_width(cl), ch = pyr.level_height(cl);
    // Child columns ci0 (and ci0 + 1 if it exists) split the node at xm; same
    // for rows. Slab t values at the 3 planes per axis are shared by children.
    const int ci0 = 2 * e.i, cj0 = 2 * e.j;
    const int ncol = std::min(2, cw - ci0), nrow = std::min(2, ch - cj0);
    const double xs[3] = {double(ci0) * node_w[cl], std::min(double(ci0 + 1) * node_w[cl], ext_x),
                          std::min(double(ci0 + 2) * node_w[cl], ext_x)};
    const double ys[3] = {double(cj0) * node_h[cl], std::min(double(cj0 + 1) * node_h[cl], ext_y),
                          std::min(double(cj0 + 2) * node_h[cl], ext_y)};
    Span spx[2], spy[2];
    axis_spans(r, 0, xs, ncol, spx);
    axis_spans(r, 1, ys, nrow, spy);
    struct Child {
      double t2d, key;
      int i, j;
    } kids[4];
    int n = 0;
    for (int dj = 0; dj < nrow; ++dj) {
      for (int di = 0; di < ncol; ++di) {
        double enter = std::max(r.t_lo, std::max(spx[di].in, spy[dj].in));
        double exit = std::min(best, std::min(spx[di].out, spy[dj].out));
        if (!overlaps(r, enter, exit)) continue;  // footprint not crossed: node not even read
        const double t2d = enter;
        ++stats.nodes_tested;
        const HeightPyramid::MinMax mm = pyr.node(cl, ci0 + di, cj0 + dj);
        double lo = mm.lo, hi = mm.hi;
        drawn_range(r, xs[di], xs[di + 1], ys[dj], ys[dj + 1], lo, hi);
        if (!slab(r, 2, lo, hi, enter, exit) || !overlaps(r, enter, exit)) continue;
        kids[n++] = Child{t2d, enter - slack(r, enter), ci0 + di, cj0 + dj};
      }
    }
    // Insertion sort by footprint entry (n <= 4), then push farthest first;
    // the nearest is the next node.
    for (int a = 1; a < n; ++a)
      for (int b = a; b > 0 && kids[b].t2d < kids[b - 1].t2d; --b) std::swap(kids[b], kids[b - 1]);
    for (int a = n - 1; a >= 0; --a) {
      if (a > 0) {
        stack[sp++] = Entry{kids[a].key, cl, kids[a].i, kids[a].j};
      } else {
        e = Entry{kids[a].key, cl, kids[a].i, kids[a].j};
        have_next = true;
      }
      // Their data is read soon (dependent loads otherwise wait one after the
      // other on memory): the grandchildren's block, or a cell's heights.
      if (cl > 0) {
        pyr.prefetch(cl - 1, 2 * kids[a].i, 2 * kids[a].j);
      } else if (!hf.paged) {
#if defined(__GNUC__) || defined(__clang__)
        const float* h = hf.heights.data() + static_cast<std::size_t>(kids[a].j) * hf.width + kids[a].i;
        __builtin_prefetch(h);
        __builtin_prefetch(h + hf.width);
#endif
      }
    }
  }
  if (!found) return std::nullopt;
  return make_hit(r, best, hit_i, hit_j);
}

}  // namespace

}  // namespace ig::terrain
