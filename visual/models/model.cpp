#include "models/model.h"

namespace ig::models {

const char* alpha_mode_name(AlphaMode mode) {
  switch (mode) {
    case AlphaMode::Opaque: return "opaque";
    case AlphaMode::Mask: return "mask";
    case AlphaMode::Blend: return "blend";
  }
  return "opaque";
}

int Model::node_index(std::string_view name) const {
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].name == name) return int(i);
  }
  return -1;
}

std::vector<glm::mat4> Model::node_to_model() const {
  // One pass suffices: parents come before their children.
  std::vector<glm::mat4> world(nodes.size(), glm::mat4(1.0f));
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const int p = nodes[i].parent;
    world[i] = p >= 0 ? world[std::size_t(p)] * nodes[i].local : nodes[i].local;
  }
  return world;
}

std::vector<std::uint32_t> Model::mesh_instances() const {
  std::vector<std::uint32_t> count(meshes.size(), 0);
  for (const Node& n : nodes) {
    if (n.mesh >= 0 && std::size_t(n.mesh) < meshes.size()) ++count[std::size_t(n.mesh)];
  }
  return count;
}

}  // namespace ig::models
