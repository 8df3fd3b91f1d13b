#pragma once
// Entities drawn into a frame the terrain passes have drawn: model meshes
// uploaded once (EntityMesh), then every instance of a model in one
// instanced draw per mesh part, depth-tested against the terrain's depth
// (reversed-Z), lit like the terrain (the same sun, sky light and fog) and
// lowered by the same Earth-curvature drop, before the sky fills what is
// left. Camera-relative: instances arrive as eye-relative matrices computed
// in double. A scene without entities makes none of this.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/gl_objects.h"
#include "gl/render_target.h"
#include "gl/shader_program.h"
#include "gl/work_counters.h"
#include "models/model.h"

namespace ig::gl {

// One model's triangles on the GPU: a vertex and an index buffer for all its
// primitives, its textures, and one draw part per (node, primitive).
class EntityMesh {
 public:
  explicit EntityMesh(const models::Model& model);
  struct Part {
    int node = 0;                  // the node whose transform places it
    GLsizei index_count = 0;
    std::size_t first_index = 0;   // in the index buffer
    GLint base_vertex = 0;
    glm::vec4 base_color{1.0f};
    int texture = -1;              // into textures_
    bool blend = false;            // translucent (drawn after the opaque parts)
    float alpha_cutoff = -1.0f;    // alpha mask: below it discarded (-1: none)
    bool double_sided = false;
    bool unlit = false;
  };
  const std::vector<Part>& parts() const { return parts_; }
  std::size_t node_count() const { return node_count_; }
  std::uint64_t triangles() const { return triangles_; }

 private:
  friend class EntityPass;
  VertexArray vao_;
  Buffer vertices_, indices_;
  std::vector<Texture> textures_;
  std::vector<Part> parts_;
  std::size_t node_count_ = 0;
  std::uint64_t triangles_ = 0;
};

// Per instance of a mesh: each node's transform to eye-relative world
// metres (node_count matrices, in node order) and the instance's alpha.
struct EntityInstanceData {
  std::vector<glm::mat4> node_to_eye;
  float alpha = 1.0f;
};

struct EntityLighting {
  glm::mat4 view_proj{1.0f};
  float earth_radius_m = 0.0f;
  glm::vec3 sun_dir{0.0f, 0.0f, 1.0f}, light_color{1.0f}, ambient{0.3f};
  glm::vec3 fog_color{0.7f};
  float fog_k = 0.0f;
};

class EntityPass {
 public:
  explicit EntityPass(const std::string& shader_dir);
  // Into the bound target's colour and depth (the frame's depth test), as
  // pass "entities": opaque parts of every batch, then the translucent ones.
  // Each batch is one mesh and its instances. The coverage code in alpha is
  // left as the terrain passes wrote it.
  struct Batch {
    const EntityMesh* mesh;
    const std::vector<EntityInstanceData>* instances;
  };
  void draw(const RenderTarget& target, const std::vector<Batch>& batches, const EntityLighting& light,
            PassRecorder& recorder);

 private:
  // One mesh part for `count` instances whose records start at `first_record`.
  struct PartDraw {
    const EntityMesh* mesh;
    const EntityMesh::Part* part;
    std::size_t first_record;
    std::size_t count;
  };
  void draw_part(const PartDraw& d);
  ShaderProgram program_;
  Buffer instances_;          // grown as needed
  std::size_t capacity_ = 0;  // bytes
};

}  // namespace ig::gl
