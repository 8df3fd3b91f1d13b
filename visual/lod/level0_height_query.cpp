#include "lod/level0_height_query.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ig::lod {

namespace {
int bucket_side(const Level0Mesh& mesh, int asked) {
  if (asked > 0) return asked;
  const double triangles = double(mesh.indices.size() / 3);
  return std::clamp(int(std::sqrt(triangles)), 64, 2048);
}
}  // namespace

Level0HeightQuery::Level0HeightQuery(const Level0Mesh& mesh, int w, int h, int buckets)
    : mesh_(mesh), buckets_(bucket_side(mesh, buckets)), cell_x_(std::max(1, w - 1) / double(buckets_)),
      cell_y_(std::max(1, h - 1) / double(buckets_)) {
  const size_t n = size_t(buckets_) * buckets_;
  // Each triangle's bucket range, counted, then filled in triangle order.
  auto each_bucket = [&](size_t t, auto f) {
    double lo_i = 1e30, hi_i = -1e30, lo_j = 1e30, hi_j = -1e30;
    for (int k = 0; k < 3; ++k) {
      const auto s = mesh.samples[mesh.indices[t + k]];
      lo_i = std::min(lo_i, double(s.x));
      hi_i = std::max(hi_i, double(s.x));
      lo_j = std::min(lo_j, double(s.y));
      hi_j = std::max(hi_j, double(s.y));
    }
    const int last = buckets_ - 1;
    const int b0 = std::clamp(int(lo_i / cell_x_), 0, last), b1 = std::clamp(int(hi_i / cell_x_), 0, last);
    const int c0 = std::clamp(int(lo_j / cell_y_), 0, last), c1 = std::clamp(int(hi_j / cell_y_), 0, last);
    for (int c = c0; c <= c1; ++c)
      for (int b = b0; b <= b1; ++b) f(size_t(c) * buckets_ + b);
  };
  bucket_start_.assign(n + 1, 0);
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) each_bucket(t, [&](size_t k) { ++bucket_start_[k + 1]; });
  for (size_t k = 0; k < n; ++k) bucket_start_[k + 1] += bucket_start_[k];
  bucket_tris_.resize(size_t(bucket_start_[n]));
  std::vector<int> next(bucket_start_.begin(), bucket_start_.end() - 1);
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    each_bucket(t, [&](size_t k) { bucket_tris_[size_t(next[k]++)] = int(t / 3); });
}

Level0HeightQuery::OnTriangle Level0HeightQuery::evaluate(int t, double i, double j) const {
  glm::dvec2 p[3];
  double z[3];
  for (int k = 0; k < 3; ++k) {
    const auto v = mesh_.indices[size_t(t) * 3 + k];
    p[k] = glm::dvec2(mesh_.samples[v]);
    z[k] = mesh_.positions[v].z;
  }
  const double det = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
  if (det == 0.0) return {};
  const double l1 = ((i - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (j - p[0].y)) / det;
  const double l2 = ((p[1].x - p[0].x) * (j - p[0].y) - (i - p[0].x) * (p[1].y - p[0].y)) / det;
  const double l0 = 1.0 - l1 - l2;
  return {true, std::max({-l0, -l1, -l2, 0.0}), std::min({l0, l1, l2}), l0 * z[0] + l1 * z[1] + l2 * z[2]};
}

double Level0HeightQuery::height_at(double i, double j, int* hint) const {
  // Clearly inside the hinted triangle (not on an edge within rounding), no
  // other triangle holds the point (the mesh's triangles do not overlap):
  // the scan would find this one, and the same height.
  if (hint && *hint >= 0) {
    const OnTriangle h = evaluate(*hint, i, j);
    if (h.valid && h.inside > 1e-9) return h.height;
  }
  const int b = std::clamp(int(i / cell_x_), 0, buckets_ - 1), c = std::clamp(int(j / cell_y_), 0, buckets_ - 1);
  double best = std::numeric_limits<double>::quiet_NaN(), best_outside = 1e30;
  const size_t k = size_t(c) * buckets_ + b;
  for (int q = bucket_start_[k]; q < bucket_start_[k + 1]; ++q) {
    const int t = bucket_tris_[size_t(q)];
    const OnTriangle h = evaluate(t, i, j);
    if (!h.valid) continue;
    if (h.outside < best_outside) {  // inside (0) wins; else the least-outside triangle
      best_outside = h.outside;
      best = h.height;
    }
    if (h.outside == 0.0) {
      if (hint) *hint = t;
      break;
    }
  }
  return best;
}

}  // namespace ig::lod
