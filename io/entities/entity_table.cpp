#include "io/entities/entity_table.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

namespace ig::io {

using wire::CigiClamp;
using wire::CigiEntityState;

namespace {

// Body offsets (x forward, y right, z down) from a pose, in its world.
glm::dvec3 offset_from(const Pose& p, const glm::dvec3& xyz) {
  return p.position + forward_of(p.attitude) * xyz.x + right_of(p.attitude) * xyz.y - up_of(p.attitude) * xyz.z;
}

}  // namespace

glm::dquat conformal_attitude(double heading_deg, const glm::dvec3& normal) {
  const double h = glm::radians(heading_deg);
  const glm::dvec3 up = glm::normalize(normal);
  const glm::dvec3 level(std::sin(h), std::cos(h), 0.0);
  glm::dvec3 right = glm::cross(level, up);
  if (glm::length(right) < 1e-9) return attitude_from_hpr({heading_deg, 0.0, 0.0});
  right = glm::normalize(right);
  const glm::dvec3 forward = glm::cross(up, right);
  return glm::quat_cast(glm::dmat3(right, forward, up));  // body x right, y forward, z up
}

EntityTable::EntityTable(GeodeticToLocal to_local, SurfaceAt surface, EntityLimits limits)
    : to_local_(std::move(to_local)), surface_(std::move(surface)), limits_(limits) {}

void EntityTable::note(const std::string& text) const {
  if (problems_[text]++ == 0) messages_.push_back(text);
}

std::vector<std::string> EntityTable::take_messages() {
  std::vector<std::string> out;
  out.swap(messages_);
  return out;
}

void EntityTable::clear() {
  entities_.clear();
  ++counters_["resets"];
}

void EntityTable::take_control(const wire::CigiEntityControl& c, double time_s) {
  ++counters_["entity_controls"];
  if (c.state == CigiEntityState::Destroyed) {
    counters_["destroyed"] += entities_.erase(c.entity);
    return;
  }
  auto it = entities_.find(c.entity);
  if (it == entities_.end()) {
    if (entities_.size() >= limits_.max_entities) {
      ++counters_["too-many-entities"];
      note("entity " + std::to_string(c.entity) + ": more than " + std::to_string(limits_.max_entities) +
           " entities; refused");
      return;
    }
    it = entities_.emplace(c.entity, Entity{}).first;
  }
  Entity& e = it->second;
  wire::CigiEntityControl local = c;
  if (!c.attached) {
    // Clamped: the altitude is the offset above the surface.
    const double alt = c.clamp == CigiClamp::None ? c.position.z : 0.0;
    const auto p = to_local_ ? to_local_(c.position.x, c.position.y, alt) : std::nullopt;
    if (!p) {
      ++counters_["not-placeable"];
      note("entity " + std::to_string(c.entity) + ": a geodetic position on a terrain without a georeference");
      entities_.erase(it);
      return;
    }
    local.position = {p->x, p->y, c.clamp == CigiClamp::None ? p->z : c.position.z};
  }
  e.control = local;
  e.time_s = time_s;
}

void EntityTable::take(const wire::CigiEntityPackets& packets, std::span<const wire::CigiRateControl> rates,
                       double time_s) {
  // Malformed Entity and Articulated Part Controls: dropped by the decoder, counted here.
  for (const wire::QueryReject r : packets.rejects) ++counters_[std::string("rejected-") + wire::query_reject_name(r)];
  for (const auto& c : packets.controls)
    if (c.entity != wire::kCigiOwnshipEntity) take_control(c, time_s);
  for (const auto& r : rates) {
    if (r.entity == wire::kCigiOwnshipEntity || r.apply_to_part) continue;  // the ownship's: the pose intake's
    auto it = entities_.find(r.entity);
    if (it == entities_.end()) {
      ++counters_["rates-for-unknown-entity"];
      continue;
    }
    // From now on the entity moves at these rates from where it is now.
    Entity& e = it->second;
    const Pose now = extrapolated(e, time_s);
    if (e.control.attached || e.control.clamp == CigiClamp::None) e.control.position = now.position;
    else e.control.position = {now.position.x, now.position.y, e.control.position.z};
    const Hpr hpr = hpr_from_attitude(now.attitude);
    e.control.yaw_deg = float(hpr.heading_deg);
    e.control.pitch_deg = float(hpr.pitch_deg);
    e.control.roll_deg = float(hpr.roll_deg);
    e.time_s = time_s;
    const bool zero = r.velocity_mps == glm::dvec3(0.0) && r.rates_dps == glm::dvec3(0.0);
    e.rates = zero ? std::nullopt : std::optional(r);
    ++counters_["rate_controls"];
  }
  for (const auto& p : packets.parts) {
    auto it = entities_.find(p.entity);
    if (it == entities_.end()) {
      ++counters_["parts-for-unknown-entity"];
      continue;
    }
    auto& parts = it->second.parts;
    if (!parts.count(p.part) && parts.size() >= limits_.max_parts) {
      ++counters_["too-many-parts"];
      continue;
    }
    EntityPart& part = parts[p.part];
    part.enabled = p.enabled;
    for (auto [from, to] : {std::pair{&p.x_m, &part.x_m}, {&p.y_m, &part.y_m}, {&p.z_m, &part.z_m},
                            {&p.roll_deg, &part.roll_deg}, {&p.pitch_deg, &part.pitch_deg}, {&p.yaw_deg, &part.yaw_deg}})
      if (*from) *to = *from;
    ++counters_["articulated_parts"];
  }
}

Pose EntityTable::extrapolated(const Entity& e, double time_s) const {
  const auto& c = e.control;
  Hpr hpr{c.yaw_deg, c.pitch_deg, c.roll_deg};
  glm::dvec3 position = c.position;
  if (e.rates) {
    const double dt = std::max(0.0, time_s - e.time_s);
    const glm::dvec3 v = e.rates->velocity_mps;
    const glm::dquat q = attitude_from_hpr(hpr);
    glm::dvec3 move;
    if (c.attached) move = v;  // offsets along the parent's axes: x forward, y right, z down
    else if (e.rates->body_axes) move = forward_of(q) * v.x + right_of(q) * v.y - up_of(q) * v.z;
    else move = glm::dvec3(v.y, v.x, -v.z);  // north, east, down -> ENU
    position += move * dt;
    hpr.roll_deg += e.rates->rates_dps.x * dt;
    hpr.pitch_deg += e.rates->rates_dps.y * dt;
    hpr.heading_deg += e.rates->rates_dps.z * dt;
  }
  return {position, attitude_from_hpr(hpr)};
}

std::optional<EntityPose> EntityTable::resolve(std::uint16_t id, double time_s, const Pose& ownship,
                                               std::vector<std::uint16_t>& chain) const {
  const auto it = entities_.find(id);
  if (it == entities_.end()) return std::nullopt;
  const Entity& e = it->second;
  const auto& c = e.control;
  if (c.state != CigiEntityState::Active) return std::nullopt;
  if (std::find(chain.begin(), chain.end(), id) != chain.end()) {
    std::string loop;
    for (auto k : chain) loop += std::to_string(k) + " -> ";
    note("entities " + loop + std::to_string(id) + ": an attach loop; not drawn");
    return std::nullopt;
  }
  chain.push_back(id);
  EntityPose out;
  out.id = id;
  out.type = c.type;
  out.alpha = float(c.alpha) / 255.0f;
  out.parts = &e.parts;
  const Pose local = extrapolated(e, time_s);
  if (c.attached) {
    std::optional<EntityPose> parent;
    if (c.parent == wire::kCigiOwnshipEntity) {
      parent = EntityPose{};
      parent->pose = ownship;
    } else {
      parent = resolve(c.parent, time_s, ownship, chain);
    }
    if (!parent) {
      if (!entities_.count(c.parent) && c.parent != wire::kCigiOwnshipEntity)
        note("entity " + std::to_string(id) + ": its parent " + std::to_string(c.parent) +
             " does not exist; not drawn");
      return std::nullopt;
    }
    out.parent = c.parent;
    out.pose.position = offset_from(parent->pose, local.position);
    out.pose.attitude = glm::normalize(parent->pose.attitude * local.attitude);
    if (c.inherit_alpha) out.alpha = parent->alpha;
  } else {
    out.pose = local;
    if (c.clamp != CigiClamp::None) {
      const auto s = surface_ ? surface_(local.position.x, local.position.y) : std::nullopt;
      if (s) {
        out.pose.position.z = s->height_m + c.position.z;
        if (c.clamp == CigiClamp::Conformal)
          out.pose.attitude = conformal_attitude(hpr_from_attitude(local.attitude).heading_deg, s->normal);
      } else {
        note("entity " + std::to_string(id) + ": clamped off the terrain; placed at its offset");
      }
    }
  }
  return out;
}

std::optional<EntityPose> EntityTable::pose_of(std::uint16_t id, double time_s, const Pose& ownship) const {
  std::vector<std::uint16_t> chain;
  return resolve(id, time_s, ownship, chain);
}

std::vector<EntityPose> EntityTable::poses_at(double time_s, const Pose& ownship) const {
  std::vector<EntityPose> out;
  out.reserve(entities_.size());
  for (const auto& [id, e] : entities_)
    if (auto p = pose_of(id, time_s, ownship)) out.push_back(*p);
  return out;
}

std::optional<Pose> EntityTable::part_pose_of(std::uint16_t id, std::uint8_t part, double time_s,
                                              const Pose& ownship) const {
  const auto p = pose_of(id, time_s, ownship);
  if (!p) return std::nullopt;
  const auto it = p->parts->find(part);
  if (it == p->parts->end()) return p->pose;  // never moved: where the entity is
  const EntityPart& a = it->second;
  Pose out;
  out.position = offset_from(p->pose, glm::dvec3(a.x_m.value_or(0), a.y_m.value_or(0), a.z_m.value_or(0)));
  out.attitude = glm::normalize(
      p->pose.attitude * attitude_from_hpr({a.yaw_deg.value_or(0), a.pitch_deg.value_or(0), a.roll_deg.value_or(0)}));
  return out;
}

nlohmann::json EntityTable::summary() const {
  std::size_t active = 0;
  for (const auto& [id, e] : entities_) active += e.control.state == CigiEntityState::Active;
  nlohmann::json out = counters_;
  out["entities"] = entities_.size();
  out["active"] = active;
  out["problems"] = problems_;
  return out;
}

}  // namespace ig::io
