#pragma once
// An entity model (aircraft, vehicle, ship) as plain values: the node
// hierarchy, meshes, materials and decoded images of one glTF 2.0 file,
// validated by load_model (models/model_loader.h). No GL: a renderer uploads
// meshes and images once and draws each node's mesh with node_to_model().
//
// Everything is in glTF's axes and units (metres, +Y up, +Z front; see
// models/model_axes.h for the body axes). Nodes keep the file's hierarchy so
// articulated parts (a rudder, a turret, a radar) are moved by changing the
// local transform of the node found with node_index().

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "models/model_image.h"
#include "models/model_material.h"
#include "models/model_mesh.h"

namespace ig::models {

struct Node {
  std::string name;       // may be empty; names need not be unique in glTF
  int parent = -1;        // index into Model::nodes, always below this node's own; -1: a root
  glm::mat4 local{1.0f};  // this node's frame in its parent's (the model's for a root)
  int mesh = -1;          // index into Model::meshes; -1: a transform only
};

// Model-space extent of every triangle of every node, with the nodes'
// transforms as loaded (articulated parts at rest).
struct Bounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
  glm::vec3 centre{0.0f};  // of the sphere: the box's centre
  float radius = 0.0f;     // smallest sphere about `centre` holding every vertex

  glm::vec3 size() const { return max - min; }
};

struct Model {
  std::string source;  // the file it was loaded from
  // Parents before children (a node's parent index is below its own).
  std::vector<Node> nodes;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Image> images;
  Bounds bounds;
  // Triangles drawn: each node's mesh counted once per node, so a mesh
  // instanced by several nodes counts several times.
  std::uint64_t triangles = 0;

  // The first node named `name`; -1 when there is none.
  int node_index(std::string_view name) const;
  // Every node's transform to model space (the product of its local
  // transform and its ancestors'), indexed like `nodes`.
  std::vector<glm::mat4> node_to_model() const;
  // How many nodes draw each mesh, indexed like `meshes`.
  std::vector<std::uint32_t> mesh_instances() const;
};

}  // namespace ig::models
