#pragma once
// The project's entity models as plain descriptions (nodes, meshes,
// materials, one texture), built from boxes and lofts to the figures of
// models/tools/entity_designs.h. make_entity_models writes them as .glb.
// Part of the generator only: the IG never links this.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "models/tools/entity_designs.h"

namespace ig::models::shapes {

// One mesh of one material (one glTF primitive), triangles counter-clockwise
// seen from outside, glTF's front.
struct MeshData {
  std::string name;
  int material = 0;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> texcoords;  // one per position
  std::vector<std::uint32_t> indices;

  std::uint64_t triangles() const { return indices.size() / 3; }
};

struct MaterialData {
  std::string name;
  glm::vec4 base_color{1.0f};
  bool textured = false;  // uses EntityModel::texture as its base colour texture
  bool blend = false;     // alphaMode BLEND
  bool double_sided = false;
};

struct NodeData {
  std::string name;
  int parent = -1;
  glm::vec3 translation{0.0f};
  int mesh = -1;
};

struct TextureData {
  std::string name;
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
};

struct EntityModel {
  std::string file;  // e.g. "aircraft.glb"
  std::vector<NodeData> nodes;  // parents first; node 0 the root
  std::vector<MeshData> meshes;
  std::vector<MaterialData> materials;
  std::optional<TextureData> texture;

  std::uint64_t triangles() const;  // counting each node's mesh once per node
};

EntityModel build_aircraft(designs::Detail detail);
EntityModel build_ground_vehicle(designs::Detail detail);
EntityModel build_ship(designs::Detail detail);
// The farthest level of each: one box (12 triangles) of the model's extent
// and main colour, for entities a few pixels across, where a CPU rasterizer
// pays per vertex (docs/models.md).
EntityModel build_far(const std::string& file, glm::vec3 lo, glm::vec3 hi, glm::vec4 colour);

}  // namespace ig::models::shapes
