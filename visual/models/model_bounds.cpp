#include "models/model_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace ig::models {

namespace {

// Calls f(model-space position) for every vertex of every drawn node. The
// loader keeps only vertices that triangles use, so this is at most three
// per drawn triangle: bounded by the triangle cap.
template <typename F>
bool for_each_vertex(const Model& model, const std::vector<glm::mat4>& world, F&& f) {
  bool any = false;
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    const int m = model.nodes[i].mesh;
    if (m < 0 || std::size_t(m) >= model.meshes.size()) continue;
    for (const Primitive& p : model.meshes[std::size_t(m)].primitives) {
      for (const glm::vec3& v : p.positions) {
        f(glm::vec3(world[i] * glm::vec4(v, 1.0f)));
        any = true;
      }
    }
  }
  return any;
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

std::optional<Bounds> compute_bounds(const Model& model) {
  const std::vector<glm::mat4> world = model.node_to_model();
  Bounds b;
  b.min = glm::vec3(std::numeric_limits<float>::max());
  b.max = glm::vec3(std::numeric_limits<float>::lowest());
  bool ok = true;
  const bool any = for_each_vertex(model, world, [&](const glm::vec3& p) {
    if (!finite(p)) ok = false;
    b.min = glm::min(b.min, p);
    b.max = glm::max(b.max, p);
  });
  if (!any || !ok) return std::nullopt;
  b.centre = 0.5f * (b.min + b.max);
  if (!finite(b.centre)) return std::nullopt;
  double r2 = 0.0;
  for_each_vertex(model, world, [&](const glm::vec3& p) {
    const glm::dvec3 d = glm::dvec3(p) - glm::dvec3(b.centre);
    r2 = std::max(r2, glm::dot(d, d));
  });
  // Rounded up so float vertices at the far corner stay inside.
  b.radius = float(std::sqrt(r2)) * (1.0f + 1e-6f);
  if (!std::isfinite(b.radius)) return std::nullopt;
  return b;
}

}  // namespace ig::models
