#pragma once
// A scenario's scripted entities (io::Scenario::entities) placed at a sim
// time: each moved along its path (placed on the terrain like the
// ownship's), clamped to the surface at every frame when asked, attached to
// its parent, as the instances the entity renderer draws. Deterministic:
// the same time gives the same places, so ig run replays traffic exactly.

#include <map>
#include <vector>

#include "io/path_interpolator.h"
#include "io/pose.h"
#include "io/scenario.h"
#include "render/entity_renderer.h"
#include "terrain/heightfield.h"

namespace ig::session {

class ScenarioEntities {
 public:
  // Throws io::ScenarioError for a path the terrain cannot place.
  ScenarioEntities(const std::vector<io::EntitySpec>& entities, const terrain::Heightfield& hf);
  // Every entity at sim time t_s; ownship: entity 0, for those attached to it.
  std::vector<render::EntityInstance> at(double t_s, const io::Pose& ownship) const;
  bool empty() const { return entities_.empty(); }

 private:
  struct Entity {
    io::EntitySpec spec;
    io::PathInterpolator path;
  };
  io::Pose place(const Entity& e, double t_s, const io::Pose& ownship, int depth) const;
  const terrain::Heightfield& hf_;
  std::vector<Entity> entities_;
  std::map<std::uint16_t, std::size_t> index_;  // id -> entities_
};

}  // namespace ig::session
