#include "render/entity_renderer.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "models/model_loader.h"

namespace ig::render {
namespace {

// The body-axis size of a box in glTF's axes: x length along +Z, y width
// along X, z height along +Y.
void add_face(models::Primitive& p, glm::vec3 n, glm::vec3 u, glm::vec3 v, glm::vec3 centre) {
  const auto base = std::uint32_t(p.positions.size());
  for (const glm::vec2 s : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
    p.positions.push_back(centre + n + s.x * u + s.y * v);
    p.normals.push_back(glm::normalize(n));
  }
  // Counter-clockwise seen from outside: u x v = n.
  p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

}  // namespace

glm::mat4 articulation_in_gltf(const EntityPartPose& part) {
  // Body axes in glTF's: forward +Z, right -X, down -Y.
  const glm::vec3 forward(0, 0, 1), right(-1, 0, 0), down(0, -1, 0);
  const glm::vec3& o = part.offset_m;
  const glm::vec3& a = glm::radians(part.roll_pitch_yaw_deg);
  glm::mat4 m = glm::translate(glm::mat4(1.0f), forward * o.x + right * o.y + down * o.z);
  m = glm::rotate(m, a.z, down);     // yaw: nose right
  m = glm::rotate(m, a.y, right);    // pitch: nose up
  return glm::rotate(m, a.x, forward);  // roll: right side down
}

namespace {
// Each node's transform to model space with the moved parts' local
// transforms changed (parents come before children).
std::vector<glm::mat4> moved_nodes(const std::vector<models::Node>& nodes, const std::map<std::uint8_t, int>& part_nodes,
                                   const std::vector<EntityPartPose>& parts) {
  std::vector<glm::mat4> local(nodes.size());
  for (std::size_t k = 0; k < nodes.size(); ++k) local[k] = nodes[k].local;
  for (const EntityPartPose& p : parts) {
    const auto it = part_nodes.find(p.id);
    if (it == part_nodes.end()) continue;
    local[std::size_t(it->second)] = p.enabled ? local[std::size_t(it->second)] * articulation_in_gltf(p) : glm::mat4(0.0f);
  }
  std::vector<glm::mat4> out(nodes.size());
  for (std::size_t k = 0; k < nodes.size(); ++k)
    out[k] = nodes[k].parent < 0 ? local[k] : out[std::size_t(nodes[k].parent)] * local[k];
  return out;
}
}  // namespace

glm::dmat4 ig_body_from_gltf() {
  return glm::dmat4(glm::dvec4(-1.0, 0.0, 0.0, 0.0),  // glTF +X (left)  -> body -x
                    glm::dvec4(0.0, 0.0, 1.0, 0.0),   // glTF +Y (up)    -> body +z
                    glm::dvec4(0.0, 1.0, 0.0, 0.0),   // glTF +Z (front) -> body +y
                    glm::dvec4(0.0, 0.0, 0.0, 1.0));
}

models::Model box_model(const glm::vec3& size_m) {
  const glm::vec3 h(size_m.y / 2, size_m.z / 2, size_m.x / 2);  // glTF half extents: x width, y height, z length
  const glm::vec3 centre(0.0f, h.y, 0.0f);
  models::Model m;
  m.source = "(box)";
  models::Primitive p;
  p.material = 0;
  add_face(p, {h.x, 0, 0}, {0, 0, -h.z}, {0, h.y, 0}, centre);
  add_face(p, {-h.x, 0, 0}, {0, 0, h.z}, {0, h.y, 0}, centre);
  add_face(p, {0, h.y, 0}, {h.x, 0, 0}, {0, 0, -h.z}, centre);
  add_face(p, {0, -h.y, 0}, {h.x, 0, 0}, {0, 0, h.z}, centre);
  add_face(p, {0, 0, h.z}, {h.x, 0, 0}, {0, h.y, 0}, centre);
  add_face(p, {0, 0, -h.z}, {-h.x, 0, 0}, {0, h.y, 0}, centre);
  m.meshes.push_back({"box", {p}});
  models::Material orange;
  orange.name = "entity type without a model";
  orange.base_color = {0.95f, 0.55f, 0.1f, 1.0f};
  m.materials.push_back(orange);
  m.nodes.push_back({"box", -1, glm::mat4(1.0f), 0});
  m.bounds.min = centre - h;
  m.bounds.max = centre + h;
  m.bounds.centre = centre;
  m.bounds.radius = glm::length(h);
  m.triangles = 12;
  return m;
}

EntityRenderer::EntityRenderer(std::string shader_dir, std::optional<models::ModelTable> table,
                               models::ModelLimits limits, std::size_t max_drawn)
    : shader_dir_(std::move(shader_dir)), table_(std::move(table)), limits_(limits), max_drawn_(max_drawn) {}

EntityRenderer::~EntityRenderer() = default;

std::vector<std::string> EntityRenderer::take_messages() {
  std::vector<std::string> out;
  out.swap(messages_);
  return out;
}

EntityRenderer::TypeModels EntityRenderer::box_models() const {
  TypeModels t;
  const models::Model box = box_model(table_ ? table_->default_box_m : glm::vec3(4.0f, 2.0f, 1.5f));
  t.levels.push_back({std::make_unique<gl::EntityMesh>(box), box.node_to_model(), box.nodes, {}, box.bounds, 0.0});
  return t;
}

const EntityRenderer::TypeModels& EntityRenderer::models_for(std::uint16_t type) {
  auto it = types_.find(type);
  if (it != types_.end()) return it->second;
  TypeModels t;
  const models::EntityModels* entry = table_ ? table_->find(type) : nullptr;
  if (!entry) {
    messages_.push_back("entity type " + std::to_string(type) + ": no model in the model table" +
                        (table_ ? " (" + table_->source + ")" : std::string()) + "; drawn as a box");
  } else {
    for (const auto& lod : entry->lods) {
      models::ModelLoad load = models::load_model(lod.file, limits_);
      if (!load.ok()) {
        messages_.push_back("entity type " + std::to_string(type) + ": " + load.error + "; drawn as a box");
        t.levels.clear();
        break;
      }
      const models::Model& m = *load.model;
      std::map<std::uint8_t, int> part_nodes;
      for (const auto& [id, name] : entry->parts)
        if (const int node = m.node_index(name); node >= 0) part_nodes[id] = node;
      t.levels.push_back(
          {std::make_unique<gl::EntityMesh>(m), m.node_to_model(), m.nodes, part_nodes, m.bounds, lod.min_size_px});
    }
  }
  if (t.levels.empty()) t = box_models();
  return types_.emplace(type, std::move(t)).first->second;
}

EntityDrawStats EntityRenderer::draw(const Camera& camera, const glm::dvec3& world_eye, const TerrainScene& scene,
                                     const gl::RenderTarget& target, gl::PassRecorder& recorder) {
  EntityDrawStats stats;
  if (instances_.empty()) return stats;
  if (!pass_) pass_ = std::make_unique<gl::EntityPass>(shader_dir_);
  const Frustum frustum = frustum_of(camera);
  const double pixels_per_radian = target.height() / (2.0 * std::tan(glm::radians(camera.fov_y_deg) / 2.0));
  const glm::dmat4 to_body = ig_body_from_gltf();
  // Instances grouped by (type, level): one batch each.
  std::map<std::pair<std::uint16_t, int>, std::vector<gl::EntityInstanceData>> groups;
  struct Visible {
    const EntityInstance* entity;
    int level;
    double distance;
    glm::dmat4 placed;
  };
  std::vector<Visible> visible;
  visible.reserve(instances_.size());
  for (const EntityInstance& e : instances_) {
    const TypeModels& t = models_for(e.type);
    const glm::dvec3 rel = e.position - world_eye;
    const glm::dmat4 placed = glm::translate(glm::dmat4(1.0), rel) * glm::dmat4(glm::mat3_cast(e.attitude)) * to_body;
    // The bounding sphere of the finest level (coarser levels lie within it).
    const models::Bounds& b = t.levels.front().bounds;
    glm::dvec3 centre = glm::dvec3(placed * glm::dvec4(glm::dvec3(b.centre), 1.0));
    if (camera.earth_radius_m > 0.0) centre.z -= glm::dot(glm::dvec2(centre), glm::dvec2(centre)) / (2.0 * camera.earth_radius_m);
    const double radius = b.radius;
    bool inside = true;
    for (const glm::dvec4& p : frustum.planes)
      if (glm::dot(glm::dvec3(p), centre) + p.w < -radius) inside = false;
    const double distance = std::max(glm::length(centre) - radius, 1e-3);
    const double size_px = 2.0 * radius / distance * pixels_per_radian;
    int level = 0;
    while (level + 1 < int(t.levels.size()) && size_px < t.levels[std::size_t(level)].min_size_px) ++level;
    if (!inside || size_px < t.levels[std::size_t(level)].min_size_px) {
      ++stats.culled;
      continue;
    }
    visible.push_back({&e, level, distance, placed});
  }
  // Beyond the budget: the nearest are drawn, the rest counted.
  if (visible.size() > max_drawn_) {
    std::nth_element(visible.begin(), visible.begin() + std::ptrdiff_t(max_drawn_), visible.end(),
                     [](const Visible& a, const Visible& b) { return a.distance < b.distance; });
    stats.over_budget = visible.size() - max_drawn_;
    visible.resize(max_drawn_);
  }
  for (const Visible& v : visible) {
    const EntityInstance& e = *v.entity;
    const int level = v.level;
    const glm::dmat4& placed = v.placed;
    const Level& l = types_.at(e.type).levels[std::size_t(level)];
    gl::EntityInstanceData data;
    data.alpha = e.alpha;
    const std::vector<glm::mat4> moved = e.parts.empty() ? std::vector<glm::mat4>() : moved_nodes(l.nodes, l.part_nodes, e.parts);
    const std::vector<glm::mat4>& nodes = e.parts.empty() ? l.node_to_model : moved;
    data.node_to_eye.reserve(nodes.size());
    for (const glm::mat4& n : nodes) data.node_to_eye.push_back(glm::mat4(placed * glm::dmat4(n)));
    groups[{e.type, level}].push_back(std::move(data));
    ++stats.in_view;
  }
  std::vector<gl::EntityPass::Batch> batches;
  for (const auto& [key, instances] : groups) {
    const Level& l = types_.at(key.first).levels[std::size_t(key.second)];
    batches.push_back({l.mesh.get(), &instances});
    stats.triangles += l.mesh->triangles() * instances.size();
  }
  stats.batches = batches.size();
  const environment::SkyLight& sky = scene.sky_light();
  gl::EntityLighting light;
  light.view_proj = camera.view_projection();
  light.earth_radius_m = float(camera.earth_radius_m);
  light.sun_dir = sky.light_direction;
  light.light_color = sky.light_colour;
  light.ambient = sky.ambient;
  light.fog_color = sky.sky_horizon;
  light.fog_k = float(scene.fog_k());
  pass_->draw(target, batches, light, recorder);
  return stats;
}

}  // namespace ig::render
