#include "models/node_graph.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "models/model_error.h"

namespace ig::models {

namespace {

std::string node_name(const tinygltf::Model& gltf, int i) {
  return describe("node", std::size_t(i), gltf.nodes[std::size_t(i)].name);
}

bool all_finite(const std::vector<double>& v) {
  for (double x : v) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}

// parent[i]: the node listing i as a child, -1 for none. Throws for a
// child that does not exist or a node with two parents.
std::vector<int> parents(const tinygltf::Model& gltf) {
  const std::size_t n = gltf.nodes.size();
  std::vector<int> parent(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    for (int c : gltf.nodes[i].children) {
      if (c < 0 || std::size_t(c) >= n) {
        throw ModelError(node_name(gltf, int(i)) + " lists child " + std::to_string(c) + ", which does not exist (" +
                         std::to_string(n) + " nodes)");
      }
      if (std::size_t(c) == i) throw ModelError("node hierarchy loop: " + node_name(gltf, c) + " is its own child");
      if (parent[std::size_t(c)] == int(i)) {
        throw ModelError(node_name(gltf, int(i)) + " lists " + node_name(gltf, c) + " twice as a child");
      }
      if (parent[std::size_t(c)] >= 0) {
        throw ModelError(node_name(gltf, c) + " has two parents: " + node_name(gltf, parent[std::size_t(c)]) +
                         " and " + node_name(gltf, int(i)));
      }
      parent[std::size_t(c)] = int(i);
    }
  }
  return parent;
}

// With one parent each, the nodes not below a parentless node lie on loops.
// Follows parents from each node; a walk meeting itself is a loop.
void refuse_loops(const tinygltf::Model& gltf, const std::vector<int>& parent) {
  const std::size_t n = parent.size();
  enum : std::uint8_t { Unknown, OnWalk, Rooted };
  std::vector<std::uint8_t> state(n, Unknown);
  std::vector<int> walk;
  for (std::size_t start = 0; start < n; ++start) {
    walk.clear();
    int i = int(start);
    while (i >= 0 && state[std::size_t(i)] == Unknown) {
      state[std::size_t(i)] = OnWalk;
      walk.push_back(i);
      i = parent[std::size_t(i)];
    }
    if (i >= 0 && state[std::size_t(i)] == OnWalk) {
      // The loop: from i up its parents back to i (at most a few names shown).
      std::string chain = node_name(gltf, i);
      int j = parent[std::size_t(i)];
      for (int shown = 0; j != i && shown < 8; ++shown, j = parent[std::size_t(j)]) chain += " <- " + node_name(gltf, j);
      chain += j == i ? " <- " + node_name(gltf, i) : " <- ...";
      throw ModelError("node hierarchy loop (child <- parent): " + chain);
    }
    for (int w : walk) state[std::size_t(w)] = Rooted;
  }
}

glm::mat4 local_transform(const tinygltf::Model& gltf, int i, std::vector<std::string>& warnings) {
  const tinygltf::Node& node = gltf.nodes[std::size_t(i)];
  if (!all_finite(node.matrix) || !all_finite(node.translation) || !all_finite(node.rotation) ||
      !all_finite(node.scale)) {
    throw ModelError(node_name(gltf, i) + ": its transform has a NaN or infinite value");
  }
  if (!node.matrix.empty()) {
    if (node.matrix.size() == 16) {
      glm::mat4 m;
      for (int k = 0; k < 16; ++k) glm::value_ptr(m)[k] = float(node.matrix[std::size_t(k)]);  // column-major, as glTF
      return m;
    }
    warnings.push_back(node_name(gltf, i) + ": matrix has " + std::to_string(node.matrix.size()) +
                       " values, not 16: identity used");
    return glm::mat4(1.0f);
  }
  glm::mat4 m(1.0f);
  if (node.translation.size() == 3) {
    m = glm::translate(m, glm::vec3(float(node.translation[0]), float(node.translation[1]), float(node.translation[2])));
  } else if (!node.translation.empty()) {
    warnings.push_back(node_name(gltf, i) + ": translation without 3 values ignored");
  }
  if (node.rotation.size() == 4) {
    // glTF stores x, y, z, w; glm::quat's constructor takes w first.
    glm::quat q(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]), float(node.rotation[2]));
    const float len = glm::length(q);
    if (len > 1e-6f && std::isfinite(len)) {
      m *= glm::mat4_cast(q / len);
    } else {
      warnings.push_back(node_name(gltf, i) + ": zero rotation quaternion ignored");
    }
  } else if (!node.rotation.empty()) {
    warnings.push_back(node_name(gltf, i) + ": rotation without 4 values ignored");
  }
  if (node.scale.size() == 3) {
    m = glm::scale(m, glm::vec3(float(node.scale[0]), float(node.scale[1]), float(node.scale[2])));
  } else if (!node.scale.empty()) {
    warnings.push_back(node_name(gltf, i) + ": scale without 3 values ignored");
  }
  return m;
}

}  // namespace

SceneNodes scene_nodes(const tinygltf::Model& gltf, std::vector<std::string>& warnings) {
  const std::vector<int> parent = parents(gltf);
  refuse_loops(gltf, parent);

  // The roots to draw.
  std::vector<int> roots;
  const int n_scenes = int(gltf.scenes.size());
  if (n_scenes == 0) {
    for (std::size_t i = 0; i < parent.size(); ++i) {
      if (parent[i] < 0) roots.push_back(int(i));
    }
    if (!roots.empty()) warnings.push_back("no scene: drawing all " + std::to_string(roots.size()) + " root nodes");
  } else {
    int scene = gltf.defaultScene;
    if (scene >= n_scenes || scene < -1) {
      warnings.push_back("default scene " + std::to_string(scene) + " does not exist (" + std::to_string(n_scenes) +
                         " scenes): drawing scene 0");
      scene = 0;
    }
    if (scene < 0) scene = 0;  // no default named: the first
    std::vector<bool> listed(parent.size(), false);
    for (int r : gltf.scenes[std::size_t(scene)].nodes) {
      if (r < 0 || std::size_t(r) >= parent.size()) {
        warnings.push_back("scene " + std::to_string(scene) + " lists node " + std::to_string(r) +
                           ", which does not exist: skipped");
      } else if (parent[std::size_t(r)] >= 0) {
        warnings.push_back("scene " + std::to_string(scene) + " lists " + node_name(gltf, r) +
                           ", which is not a root (its parent is node " + std::to_string(parent[std::size_t(r)]) +
                           "): skipped");
      } else if (!listed[std::size_t(r)]) {
        listed[std::size_t(r)] = true;
        roots.push_back(r);
      }
    }
  }

  // Depth first, parents before children, children in the file's order.
  SceneNodes out;
  std::vector<std::pair<int, int>> stack;  // (glTF node, parent's output index)
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, -1);
  while (!stack.empty()) {
    const auto [node, up] = stack.back();
    stack.pop_back();
    const int self = int(out.source.size());
    out.source.push_back(node);
    out.parent.push_back(up);
    out.local.push_back(local_transform(gltf, node, warnings));
    const auto& children = gltf.nodes[std::size_t(node)].children;
    for (auto it = children.rbegin(); it != children.rend(); ++it) stack.emplace_back(*it, self);
  }
  return out;
}

}  // namespace ig::models
