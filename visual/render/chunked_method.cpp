#include "render/chunked_method.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ig::render {

namespace {
constexpr int Q = lod::kChunkQuads;
constexpr int kLog2Q = 5;  // 2^5 = Q: a chunk's corners lie on the grid of any chunk up to 5 levels coarser
static_assert((1 << kLog2Q) == Q);
// Skirts reach this far below the lowest height they must cover, so a
// skirt bottom never coincides with a surface.
constexpr float kSkirtMarginM = 1.0f;
}  // namespace

ChunkedMethod::ChunkedMethod(const TerrainScene& scene, const std::string& shader_dir, options::ChunkedOptions options)
    : TauMethod("chunked", scene, shader_dir, "chunked.vert", options.tau_px, options.horizon_culling),
      tree_(scene.heightfield()) {
  // Vertices (x, y, skirt side + 1 or 0, pad): the surface grid, then each
  // side's edge again as the skirt's lower edge.
  std::vector<std::int16_t> verts;
  auto vertex = [&](int x, int y, int skirt) {
    verts.insert(verts.end(), {std::int16_t(x), std::int16_t(y), std::int16_t(skirt), 0});
    return std::uint32_t(verts.size() / 4 - 1);
  };
  for (int j = 0; j <= Q; ++j)
    for (int i = 0; i <= Q; ++i) vertex(i, j, 0);
  auto surface = [](int x, int y) { return std::uint32_t(y * (Q + 1) + x); };
  std::vector<std::uint32_t> idx;
  for (int j = 0; j < Q; ++j)
    for (int i = 0; i < Q; ++i)
      idx.insert(idx.end(), {surface(i, j), surface(i + 1, j), surface(i + 1, j + 1), surface(i, j),
                             surface(i + 1, j + 1), surface(i, j + 1)});
  surface_indices_ = int(idx.size());
  for (int side = 0; side < 4; ++side) {
    auto edge = [side](int t) {
      switch (side) {
        case 0: return glm::ivec2(t, 0);
        case 1: return glm::ivec2(Q, t);
        case 2: return glm::ivec2(t, Q);
        default: return glm::ivec2(0, t);
      }
    };
    std::vector<std::uint32_t> low;
    for (int t = 0; t <= Q; ++t) low.push_back(vertex(edge(t).x, edge(t).y, side + 1));
    for (int t = 0; t < Q; ++t) {
      const std::uint32_t a = surface(edge(t).x, edge(t).y), b = surface(edge(t + 1).x, edge(t + 1).y);
      // Front faces outwards: a skirt is seen from the neighbouring chunk's
      // side (where it covers a crack), so back-face culling keeps it.
      if (side == 0 || side == 1)
        idx.insert(idx.end(), {a, low[t + 1], b, a, low[t], low[t + 1]});
      else
        idx.insert(idx.end(), {a, b, low[t + 1], a, low[t + 1], low[t]});
    }
  }
  mesh_ = gl::StaticMesh(verts, 4, {{2, 0}, {1, 2}});
  mesh_.add_indices(idx);
}

std::vector<std::string> ChunkedMethod::column_names() const {
  return {"chunks_drawn", "level_min", "level_max", "skirt_triangles", "hidden_boxes"};
}

namespace {
// Refines from node k while its projected error exceeds tau_px, culling
// against the frustum; appends the chunks to draw.
void select_from(const lod::ChunkQuadtree& tree, int k, const Camera& camera, const Frustum& frustum, double ppr,
                 double tau_px, std::vector<ChunkedMethod::DrawnChunk>& out) {
  const lod::ChunkNode& n = tree.node(k);
  glm::dvec3 lo, hi;
  tree.box(n, lo, hi);
  if (!frustum.intersects_box(lo - camera.position, hi - camera.position)) return;
  const double d = lod::box_distance(camera.position, lo, hi);
  if (!n.leaf() && n.error_m / std::max(d, camera.near_m) * ppr > tau_px) {
    for (int c : n.children)
      if (c >= 0) select_from(tree, c, camera, frustum, ppr, tau_px, out);
    return;
  }
  out.push_back({k, d, 0.0f});
}
}  // namespace

lod::SceneRequests ChunkedMethod::update(const Camera& camera) {
  drawn_ = select(camera);
  // After the skirts: their depth follows every chunk selected, hidden or not.
  const auto box_of = [&](const DrawnChunk& d) {
    lod::HorizonCulling::Box b;
    tree_.box(tree_.node(d.node), b.lo, b.hi);
    return b;
  };
  // A chunk's triangles span one quad of its stride.
  const auto span_of = [&](const DrawnChunk& d) { return tree_.node(d.node).stride; };
  remove_hidden(camera, drawn_, box_of, span_of);
  return {};
}

std::vector<ChunkedMethod::DrawnChunk> ChunkedMethod::select(const Camera& camera) const {
  std::vector<DrawnChunk> drawn;
  select_from(tree_, 0, camera, frustum_of(camera), viewport_pixels_per_radian(camera), tau_px_, drawn);

  // Skirt depth. A crack lies between this chunk's edge and a coarser
  // neighbour's edge over the same segment. Both edges interpolate DEM
  // samples: the neighbour's edge is within its error delta_n of the samples
  // on this chunk's edge, so it is never below min_h - delta_n (min_h: this
  // chunk's lowest sample). When the neighbour is at most 5 levels coarser,
  // this chunk's corners are vertices of its grid, so its edge over the
  // segment interpolates samples of this chunk's edge only: never below
  // min_h. A skirt down to min_h (or min_h - the largest delta drawn more
  // than 5 levels up) thus closes every crack, whatever the levels. (A
  // coarser chunk's own skirt covers the case where its edge is the upper one:
  // the finer edge interpolates samples of its edge, never below its min_h.)
  std::vector<float> coarse_error(size_t(tree_.depth()) + 2, 0.0f);  // [k]: max error drawn at levels < k
  for (const DrawnChunk& d : drawn) {
    const lod::ChunkNode& n = tree_.node(d.node);
    coarse_error[size_t(n.level) + 1] = std::max(coarse_error[size_t(n.level) + 1], n.own_error_m);
  }
  for (size_t k = 1; k < coarse_error.size(); ++k) coarse_error[k] = std::max(coarse_error[k], coarse_error[k - 1]);
  for (DrawnChunk& d : drawn) {
    const lod::ChunkNode& n = tree_.node(d.node);
    const float far_coarse = n.level > kLog2Q ? coarse_error[size_t(n.level - kLog2Q)] : 0.0f;
    d.skirt_bottom_m = n.heights.min_m - far_coarse - kSkirtMarginM;
  }
  // Nearest first, so the early depth test rejects what nearer chunks hide.
  std::stable_sort(drawn.begin(), drawn.end(),
                   [](const DrawnChunk& a, const DrawnChunk& b) { return a.distance_m < b.distance_m; });
  return drawn;
}

MethodFrameStats ChunkedMethod::draw(const Camera& camera, const gl::RenderTarget&) {
  MethodFrameStats stats;
  long long skirt_triangles = 0;
  int lmin = tree_.depth(), lmax = 0;
  if (!drawn_.empty()) {
    stats.passes = "terrain";
    const Placement placement = begin_draw(camera);
    const gl::Uniform stride(program_, "u_stride"), skirt_sides(program_, "u_skirt_sides");
    const gl::Uniform skirt_bottom(program_, "u_skirt_bottom");
    for (const DrawnChunk& d : drawn_) {
      const lod::ChunkNode& n = tree_.node(d.node);
      int sides = 0;
      for (int s = 0; s < 4; ++s)
        if (!n.on_dem_edge[s]) {
          sides |= 1 << s;
          skirt_triangles += 2LL * n.edge_segments[s];
        }
      place(placement, camera, n.i0, n.j0);
      stride.set(n.stride);
      skirt_sides.set(sides);
      skirt_bottom.set(d.skirt_bottom_m);
      mesh_.draw(0, 0, sides ? mesh_.index_count(0) : surface_indices_);
      stats.triangles += n.triangles;
      lmin = std::min(lmin, n.level);
      lmax = std::max(lmax, n.level);
    }
  }
  stats.triangles += skirt_triangles;
  stats.columns = {{"chunks_drawn", double(drawn_.size())},
                   {"level_min", drawn_.empty() ? 0.0 : double(lmin)},
                   {"level_max", double(lmax)},
                   {"skirt_triangles", double(skirt_triangles)},
                   {"hidden_boxes", double(hidden_boxes())}};
  return stats;
}

std::optional<double> ChunkedMethod::error_bound_px(const Camera& camera, int viewport_height_px) const {
  double worst = 0.0;
  for (const DrawnChunk& d : drawn_)
    worst = std::max(worst, tree_.node(d.node).own_error_m / std::max(d.distance_m, camera.near_m));
  return worst * pixels_per_radian(camera, viewport_height_px);
}

}  // namespace ig::render
