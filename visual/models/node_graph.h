#pragma once
// The nodes a model draws: the scene's hierarchy, checked and flattened.
// Internal to the loader.
//
// glTF requires the nodes to form disjoint trees; TinyGLTF does not check
// it. A node listed as a child by two parents, or a loop of children, would
// make a naive traversal draw parts twice or never end; both are refused.
// Traversal is iterative (a chain of a million nodes needs no deep stack).

#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <tiny_gltf.h>

namespace ig::models {

struct SceneNodes {
  // Per drawn node, parents before children: the glTF node it came from,
  // its parent (an index into these vectors, -1 for a root) and its local
  // transform.
  std::vector<int> source;
  std::vector<int> parent;
  std::vector<glm::mat4> local;
};

// The nodes of the default scene (else scene 0; with no scene at all,
// every root node), with a warning for each fallback. Throws ModelError for
// a child that does not exist, two parents, a loop or a non-finite transform.
SceneNodes scene_nodes(const tinygltf::Model& gltf, std::vector<std::string>& warnings);

}  // namespace ig::models
