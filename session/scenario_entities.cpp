#include "session/scenario_entities.h"

#include "io/entities/entity_table.h"
#include "session/scene_setup.h"

namespace ig::session {

namespace {
// Attached entities' paths are offsets: placed as given, never on the terrain.
io::PathSpec offsets_path(io::PathSpec p) {
  p.frame = io::PositionFrame::Local;
  p.altitude = io::AltitudeMode::AboveSeaLevel;
  return p;
}
}  // namespace

ScenarioEntities::ScenarioEntities(const std::vector<io::EntitySpec>& entities, const terrain::Heightfield& hf)
    : hf_(hf) {
  entities_.reserve(entities.size());
  for (const auto& e : entities) {
    // Clamped: the path's heights are above the surface, applied per frame
    // below, so the keys are placed as sea-level heights here.
    io::PathSpec path = e.parent ? offsets_path(e.path) : e.path;
    if (e.clamp != io::EntityClamp::None) path.altitude = io::AltitudeMode::AboveSeaLevel;
    index_[e.id] = entities_.size();
    entities_.push_back({e, io::PathInterpolator(e.parent ? path : place_path(path, hf))});
  }
}

io::Pose ScenarioEntities::place(const Entity& e, double t_s, const io::Pose& ownship, int depth) const {
  io::Pose p = e.path.sample(t_s);
  if (e.spec.parent) {
    // The scenario forbids loops; depth bounds it anyway.
    const io::Pose parent = *e.spec.parent == 0 || depth > 64
                                ? ownship
                                : place(entities_[index_.at(*e.spec.parent)], t_s, ownship, depth + 1);
    const glm::dvec3 o = p.position;  // x right, y forward, z up of the parent
    p.position = parent.position + io::right_of(parent.attitude) * o.x + io::forward_of(parent.attitude) * o.y +
                 io::up_of(parent.attitude) * o.z;
    p.attitude = glm::normalize(parent.attitude * p.attitude);
    return p;
  }
  if (e.spec.clamp != io::EntityClamp::None) {
    p.position.z += hf_.sample_surface(p.position.x, p.position.y);
    if (e.spec.clamp == io::EntityClamp::Conformal) {
      // The drawn surface's slope from its heights half a metre around.
      const double x = p.position.x, y = p.position.y, d = 0.5;
      const glm::dvec3 n(-(hf_.sample_surface(x + d, y) - hf_.sample_surface(x - d, y)) / (2 * d),
                         -(hf_.sample_surface(x, y + d) - hf_.sample_surface(x, y - d)) / (2 * d), 1.0);
      p.attitude = io::conformal_attitude(io::hpr_from_attitude(p.attitude).heading_deg, glm::normalize(n));
    }
  }
  return p;
}

std::vector<render::EntityInstance> ScenarioEntities::at(double t_s, const io::Pose& ownship) const {
  std::vector<render::EntityInstance> out;
  out.reserve(entities_.size());
  for (const Entity& e : entities_) {
    const io::Pose p = place(e, t_s, ownship, 0);
    out.push_back({e.spec.id, e.spec.type, p.position, p.attitude, float(e.spec.alpha), {}});
  }
  return out;
}

}  // namespace ig::session
