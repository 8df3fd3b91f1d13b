#pragma once
// Every entity a CIGI host places besides the ownship: its state, type,
// parent, alpha, clamp, dead-reckoning rates and articulated parts, and
// where it is at any time (attached to its parent, dead-reckoned from its
// last Entity Control, clamped to the surface host queries answer from).
// No GL, no sockets: the live loop hands in each datagram's entity packets
// and asks for the poses of the frame it renders (docs/entities.md).

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "io/pose.h"
#include "io/pose_intake.h"
#include "io/wire/cigi.h"
#include "io/wire/cigi_entities.h"
#include "io/wire/cigi_environment.h"

namespace ig::io {

// The surface under a point (local ENU metres): its height and upward
// normal, water included; nullopt off the terrain.
struct SurfaceSample {
  double height_m = 0.0;
  glm::dvec3 normal{0.0, 0.0, 1.0};
};
using SurfaceAt = std::function<std::optional<SurfaceSample>(double x_m, double y_m)>;

// The attitude whose up is the surface normal and whose forward is the
// heading laid on the surface: a conformal clamp.
glm::dquat conformal_attitude(double heading_deg, const glm::dvec3& normal);

struct EntityLimits {
  std::size_t max_entities = 10000;  // more ids are refused (counted "too-many-entities")
  std::size_t max_parts = 64;        // articulated parts per entity
};

// An articulated part as the host set it (fields it never set stay unset).
struct EntityPart {
  bool enabled = true;
  std::optional<float> x_m, y_m, z_m, roll_deg, pitch_deg, yaw_deg;
};

// Where an entity is drawn (and answered from) at one time.
struct EntityPose {
  std::uint16_t id = 0;
  std::uint16_t type = 0;
  Pose pose;                 // local ENU, body -> world
  float alpha = 1.0f;        // 0 transparent .. 1 opaque (the parent's when inherited)
  std::optional<std::uint16_t> parent;  // attached to this entity
  const std::map<std::uint8_t, EntityPart>* parts = nullptr;  // valid until the table changes
};

class EntityTable {
 public:
  EntityTable(GeodeticToLocal to_local, SurfaceAt surface, EntityLimits limits = {});

  // One datagram's Entity Controls (entity 0, the ownship, is the pose
  // intake's and skipped here), Articulated Part Controls and Rate Controls,
  // received at time_s (the IG's clock, as the poses asked for below).
  void take(const wire::CigiEntityPackets& packets, std::span<const wire::CigiRateControl> rates, double time_s);
  // Standby / reset from the host: every entity removed.
  void clear();

  // Every active entity at time_s. ownship: entity 0, for entities
  // attached to it. An entity whose parent is missing, inactive or part of
  // an attach loop is left out (and reported once by messages()).
  std::vector<EntityPose> poses_at(double time_s, const Pose& ownship) const;
  std::optional<EntityPose> pose_of(std::uint16_t id, double time_s, const Pose& ownship) const;
  // Where an entity's articulated part is: the entity's pose moved by the
  // part's offsets (the model's own part placement is the renderer's).
  std::optional<Pose> part_pose_of(std::uint16_t id, std::uint8_t part, double time_s, const Pose& ownship) const;

  std::size_t size() const { return entities_.size(); }
  // Problems worth telling the host (IG Message), each cause once; taken.
  std::vector<std::string> take_messages();
  nlohmann::json summary() const;

 private:
  struct Entity {
    wire::CigiEntityControl control;  // the host's last values; position local (detached) or offsets (attached)
    double time_s = 0.0;              // when they were received
    std::optional<wire::CigiRateControl> rates;
    std::map<std::uint8_t, EntityPart> parts;
  };
  // The host's values dead-reckoned to time_s: position (local, or offsets
  // when attached) and attitude (world, or relative to the parent).
  Pose extrapolated(const Entity& e, double time_s) const;
  // `chain`: the entities being resolved below this one (a repeat is a loop).
  std::optional<EntityPose> resolve(std::uint16_t id, double time_s, const Pose& ownship,
                                    std::vector<std::uint16_t>& chain) const;
  void note(const std::string& text) const;
  void take_control(const wire::CigiEntityControl& c, double time_s);

  GeodeticToLocal to_local_;
  SurfaceAt surface_;
  EntityLimits limits_;
  std::map<std::uint16_t, Entity> entities_;
  std::map<std::string, std::uint64_t> counters_;
  mutable std::map<std::string, std::uint64_t> problems_;  // reported causes -> times seen
  mutable std::vector<std::string> messages_;
};

}  // namespace ig::io
