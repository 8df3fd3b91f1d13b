#pragma once
// The entities of a frame (aircraft, vehicles, ships a host or a scenario
// places), drawn after the terrain into every view: each entity type's
// model from the model table (models/model_table.h), loaded on first use,
// the level of detail chosen by the entity's size on screen; a type with no
// model, or whose model is refused, drawn as a box of the table's default
// size and reported once. Frustum-culled per entity, instanced per model
// level, camera-relative (eye-relative matrices computed in double). Made
// only once a frame has an entity: a scene without entities links no
// entity shader and allocates nothing (docs/entities.md).

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "gl/entity_pass.h"
#include "gl/render_target.h"
#include "gl/work_counters.h"
#include "models/model.h"
#include "models/model_limits.h"
#include "models/model_table.h"
#include "render/camera.h"
#include "render/terrain_scene.h"

namespace ig::render {

// An articulated part as a host moves it (CIGI Articulated Part Control):
// offsets (x forward, y right, z down, metres) and roll, pitch, yaw (deg)
// from the part's place in the model; disabled: not drawn. The model
// table's `parts` names the node each id moves.
struct EntityPartPose {
  std::uint8_t id = 0;
  bool enabled = true;
  glm::vec3 offset_m{0.0f};
  glm::vec3 roll_pitch_yaw_deg{0.0f};
};

// One entity in one frame: its type, where it is (the pose's world frame,
// as the ownship), how opaque and how its parts are moved.
struct EntityInstance {
  std::uint16_t id = 0;
  std::uint16_t type = 0;
  glm::dvec3 position{0.0};
  glm::dquat attitude{1.0, 0.0, 0.0, 0.0};  // body (x right, y forward, z up) -> world
  float alpha = 1.0f;
  std::vector<EntityPartPose> parts;
};

// A part's move as a transform in glTF's axes (after the node's own local
// transform): translate by the offsets, then yaw, pitch and roll about the
// body's down, right and forward axes.
glm::mat4 articulation_in_gltf(const EntityPartPose& part);

struct EntityDrawStats {
  std::size_t in_view = 0;     // entities drawn (after culling)
  std::size_t culled = 0;      // outside the frustum or too small for every level
  std::size_t over_budget = 0;  // in view but beyond the per-view budget (the farthest)
  std::size_t batches = 0;     // model levels drawn (one instanced draw per part each)
  std::uint64_t triangles = 0;
};

class EntityRenderer {
 public:
  // table: the entity type -> model table; nullopt: every type a box of the
  // default size (4 x 2 x 1.5 m). max_drawn: entities drawn per view at
  // most, the nearest (a frame rate bound for crowded scenes; the rest are
  // counted in EntityDrawStats::over_budget).
  static constexpr std::size_t kDefaultMaxDrawn = 2000;
  EntityRenderer(std::string shader_dir, std::optional<models::ModelTable> table, models::ModelLimits limits = {},
                 std::size_t max_drawn = kDefaultMaxDrawn);
  ~EntityRenderer();

  void set_instances(std::vector<EntityInstance> instances) { instances_ = std::move(instances); }
  const std::vector<EntityInstance>& instances() const { return instances_; }

  // Into `target`, after the terrain: `camera` terrain-local as the method
  // drew with, `world_eye` its world position (the instances' frame).
  EntityDrawStats draw(const Camera& camera, const glm::dvec3& world_eye, const TerrainScene& scene,
                       const gl::RenderTarget& target, gl::PassRecorder& recorder);
  // Models refused, types drawn as boxes: each said once; taken.
  std::vector<std::string> take_messages();

 private:
  struct Level {
    std::unique_ptr<gl::EntityMesh> mesh;
    std::vector<glm::mat4> node_to_model;     // at rest
    std::vector<models::Node> nodes;          // for moved parts
    std::map<std::uint8_t, int> part_nodes;   // articulated part id -> node
    models::Bounds bounds;
    double min_size_px = 0.0;
  };
  struct TypeModels {
    std::vector<Level> levels;  // finest first
  };
  const TypeModels& models_for(std::uint16_t type);
  TypeModels box_models() const;

  std::string shader_dir_;
  std::optional<models::ModelTable> table_;
  models::ModelLimits limits_;
  std::size_t max_drawn_;
  std::unique_ptr<gl::EntityPass> pass_;  // made on the first draw with an entity
  std::map<std::uint16_t, TypeModels> types_;
  std::vector<EntityInstance> instances_;
  std::vector<std::string> messages_;
};

// A box of `size_m` (x length, y width, z height; body axes) standing on its
// base at the origin, as a model in glTF's axes.
models::Model box_model(const glm::vec3& size_m);

// glTF's axes (+Y up, +Z front, +X left) to the IG's body axes (x right,
// y forward, z up).
glm::dmat4 ig_body_from_gltf();

}  // namespace ig::render
