// The project's own entity models (written by make_entity_models at build
// time into bin/models) load with their named nodes, bounds, triangle counts
// and materials as designed (models/tools/entity_designs.h), and the default
// model table points at them.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>
#include <string>

#include "models/model_axes.h"
#include "models/model_loader.h"
#include "models/model_table.h"
#include "models/tools/entity_designs.h"

namespace {

using namespace ig::models;
using designs::Detail;

const std::string kModels = std::string(IG_BIN_DIR) + "/models/";

Model load_ok(const std::string& file) {
  ModelLoad r = load_model(kModels + file);
  EXPECT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  return r.ok() ? std::move(*r.model) : Model{};
}

void expect_bounds(const Model& m, const designs::Box3& b) {
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(m.bounds.min[k], b.min[std::size_t(k)], 1e-4) << m.source << " axis " << k;
    EXPECT_NEAR(m.bounds.max[k], b.max[std::size_t(k)], 1e-4) << m.source << " axis " << k;
  }
  // The sphere holds the box's corners and is no bigger than their reach.
  const float half_diagonal = 0.5f * glm::length(m.bounds.max - m.bounds.min);
  EXPECT_LE(m.bounds.radius, half_diagonal * 1.0001f) << m.source;
  EXPECT_GT(m.bounds.radius, 0.25f * half_diagonal) << m.source;
}

void expect_nodes(const Model& m, std::initializer_list<const char*> names) {
  for (const char* n : names) EXPECT_GE(m.node_index(n), 0) << m.source << " has no node " << n;
}

TEST(EntityModels, AircraftAsDesigned) {
  const Model fine = load_ok("aircraft.glb");
  const Model coarse = load_ok("aircraft_coarse.glb");
  EXPECT_EQ(fine.triangles, designs::aircraft_triangles(Detail::Fine));
  EXPECT_EQ(coarse.triangles, designs::aircraft_triangles(Detail::Coarse));
  EXPECT_LT(coarse.triangles * 5, fine.triangles);
  expect_bounds(fine, designs::kAircraftBounds);
  expect_bounds(coarse, designs::kAircraftBounds);
  EXPECT_NEAR(fine.bounds.size().x, designs::kAircraftSpan, 1e-4);
  for (const Model* m : {&fine, &coarse}) {
    expect_nodes(*m, {"aircraft", "fuselage", "wing", "propeller", "rudder", "elevator_left", "elevator_right"});
  }
}

// A node's origin in model space (articulated parts turn about it).
glm::vec3 origin(const Model& m, const char* name) {
  const int i = m.node_index(name);
  EXPECT_GE(i, 0) << name;
  return i < 0 ? glm::vec3(NAN) : glm::vec3(m.node_to_model()[std::size_t(i)][3]);
}

void expect_near(glm::vec3 a, glm::vec3 b, const char* what) {
  EXPECT_LT(glm::length(a - b), 1e-5f) << what << ": (" << a.x << ", " << a.y << ", " << a.z << ")";
}

TEST(EntityModels, AircraftHingesAndMaterials) {
  const Model m = load_ok("aircraft.glb");
  // Hinges where the design puts them: the rudder at the fin's trailing
  // edge, the elevators at the stabiliser's, the propeller on the cowling.
  expect_near(origin(m, "rudder"), {0.0f, 0.35f, -4.4f}, "rudder");
  expect_near(origin(m, "elevator_left"), {1.0f, 0.35f, -4.4f}, "elevator_left");
  expect_near(origin(m, "elevator_right"), {-1.0f, 0.35f, -4.4f}, "elevator_right");
  expect_near(origin(m, "propeller"), {0.0f, -0.05f, 3.4f}, "propeller");
  // The rudder hangs under the fin, the elevators under the stabiliser.
  const int fin = m.node_index("vertical_fin"), stab = m.node_index("horizontal_stabilizer");
  EXPECT_EQ(m.nodes[std::size_t(m.node_index("rudder"))].parent, fin);
  EXPECT_EQ(m.nodes[std::size_t(m.node_index("elevator_left"))].parent, stab);
  // One elevator mesh drawn twice.
  const int elevator_mesh = m.nodes[std::size_t(m.node_index("elevator_left"))].mesh;
  EXPECT_EQ(m.nodes[std::size_t(m.node_index("elevator_right"))].mesh, elevator_mesh);
  EXPECT_EQ(m.mesh_instances()[std::size_t(elevator_mesh)], 2u);

  // Materials: the canopy is glass (blend), the thin blades double-sided.
  auto material_of = [&](const char* node) -> const Material& {
    const Mesh& mesh = m.meshes[std::size_t(m.nodes[std::size_t(m.node_index(node))].mesh)];
    return m.materials[std::size_t(mesh.primitives.at(0).material)];
  };
  EXPECT_EQ(material_of("canopy").alpha_mode, AlphaMode::Blend);
  EXPECT_LT(material_of("canopy").base_color.a, 0.5f);
  EXPECT_TRUE(material_of("propeller").double_sided);
  EXPECT_EQ(material_of("wing").alpha_mode, AlphaMode::Opaque);
  EXPECT_FALSE(material_of("wing").double_sided);

  // The fuselage livery: a 64 x 64 texture decoded from the embedded PNG,
  // wrapping round the fuselage, clamped along it.
  const Material& livery = material_of("fuselage");
  ASSERT_EQ(m.images.size(), 1u);
  ASSERT_EQ(livery.base_color_image, 0);
  EXPECT_EQ(livery.wrap_s, TextureWrap::Repeat);
  EXPECT_EQ(livery.wrap_t, TextureWrap::ClampToEdge);
  const Image& img = m.images[0];
  ASSERT_EQ(img.width, designs::kAircraftTextureSize);
  ASSERT_EQ(img.height, designs::kAircraftTextureSize);
  auto pixel = [&](int x, int y) {
    const std::uint8_t* p = &img.rgba[(std::size_t(y) * std::size_t(img.width) + std::size_t(x)) * 4];
    return glm::ivec4(p[0], p[1], p[2], p[3]);
  };
  EXPECT_EQ(pixel(0, 32), glm::ivec4(20, 50, 140, 255));    // cheat line along the side (u = 0)
  EXPECT_EQ(pixel(16, 2), glm::ivec4(200, 30, 25, 255));    // tail band (first rows: v = 0 is the tail)
  EXPECT_EQ(pixel(16, 61), glm::ivec4(40, 40, 40, 255));    // anti-glare on top by the nose
  EXPECT_EQ(pixel(16, 32), glm::ivec4(240, 240, 245, 255));  // white
  const Primitive& skin = m.meshes[std::size_t(m.nodes[std::size_t(m.node_index("fuselage"))].mesh)].primitives.at(0);
  EXPECT_EQ(skin.texcoords.size(), skin.positions.size());

  // The coarse level has no texture: nothing to upload, nothing missing.
  const Model coarse = load_ok("aircraft_coarse.glb");
  EXPECT_TRUE(coarse.images.empty());
  for (const Material& mat : coarse.materials) EXPECT_EQ(mat.base_color_image, -1);
}

TEST(EntityModels, GroundVehicleAsDesigned) {
  const Model fine = load_ok("ground_vehicle.glb");
  const Model coarse = load_ok("ground_vehicle_coarse.glb");
  EXPECT_EQ(fine.triangles, designs::vehicle_triangles(Detail::Fine));
  EXPECT_EQ(coarse.triangles, designs::vehicle_triangles(Detail::Coarse));
  EXPECT_LT(coarse.triangles * 5, fine.triangles);
  expect_bounds(fine, designs::kVehicleBounds);
  expect_bounds(coarse, designs::kVehicleBounds);
  EXPECT_NEAR(fine.bounds.size().z, 6.0f, 1e-4);
  for (const Model* m : {&fine, &coarse}) {
    expect_nodes(*m, {"ground_vehicle", "hull", "turret", "gun", "wheel_left_1", "wheel_left_4", "wheel_right_1",
                      "wheel_right_4"});
    // The gun elevates with the turret: it is the turret's child.
    EXPECT_EQ(m->nodes[std::size_t(m->node_index("gun"))].parent, m->node_index("turret"));
    // One wheel mesh, eight wheels: the instanced count is in `triangles`.
    const int wheel = m->nodes[std::size_t(m->node_index("wheel_left_1"))].mesh;
    EXPECT_EQ(m->mesh_instances()[std::size_t(wheel)], std::uint32_t(designs::kVehicleWheels));
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < m->meshes.size(); ++i) sum += m->meshes[i].triangle_count() * m->mesh_instances()[i];
    EXPECT_EQ(sum, m->triangles);
    EXPECT_GT(m->triangles, 7 * m->meshes[std::size_t(wheel)].triangle_count());
    // Wheels touch the ground: their axles 0.45 m up.
    EXPECT_NEAR(origin(*m, "wheel_right_3").y, 0.45f, 1e-6);
  }
}

TEST(EntityModels, ShipAsDesigned) {
  const Model fine = load_ok("ship.glb");
  const Model coarse = load_ok("ship_coarse.glb");
  EXPECT_EQ(fine.triangles, designs::ship_triangles(Detail::Fine));
  EXPECT_EQ(coarse.triangles, designs::ship_triangles(Detail::Coarse));
  EXPECT_LT(coarse.triangles * 5, fine.triangles);
  expect_bounds(fine, designs::kShipBounds);
  expect_bounds(coarse, designs::kShipBounds);
  EXPECT_NEAR(fine.bounds.size().z, designs::kShipLength, 1e-4);
  for (const Model* m : {&fine, &coarse}) {
    expect_nodes(*m, {"ship", "hull", "superstructure", "mast", "radar"});
    expect_near(origin(*m, "radar"), {0.0f, 15.0f, -1.0f}, "radar on the mast top");
  }
}

// The three kinds are told apart by colour at a glance: their main
// materials' base colours differ.
TEST(EntityModels, DistinguishableColours) {
  auto main_colour = [](const char* file, const char* node) {
    const Model m = load_ok(file);
    const Mesh& mesh = m.meshes[std::size_t(m.nodes[std::size_t(m.node_index(node))].mesh)];
    return glm::vec3(m.materials[std::size_t(mesh.primitives.at(0).material)].base_color);
  };
  const glm::vec3 aircraft = main_colour("aircraft.glb", "wing");
  const glm::vec3 vehicle = main_colour("ground_vehicle.glb", "hull");
  const glm::vec3 ship = main_colour("ship.glb", "hull");
  EXPECT_GT(glm::length(aircraft - vehicle), 0.2f);
  EXPECT_GT(glm::length(aircraft - ship), 0.2f);
  EXPECT_GT(glm::length(vehicle - ship), 0.2f);
}

// glTF's axes to the body axes: the nose forward (+x), the left wing tip
// to the left (-y), the fin up (-z).
TEST(EntityModels, BodyAxes) {
  const Model m = load_ok("aircraft.glb");
  const glm::mat4 b = body_from_gltf();
  const glm::vec3 nose = b * glm::vec4(0.0f, 0.0f, m.bounds.max.z, 1.0f);
  const glm::vec3 left_tip = b * glm::vec4(m.bounds.max.x, 0.0f, 0.0f, 1.0f);
  const glm::vec3 fin_top = b * glm::vec4(0.0f, m.bounds.max.y, 0.0f, 1.0f);
  expect_near(nose, {3.8f, 0.0f, 0.0f}, "nose");
  expect_near(left_tip, {0.0f, -6.0f, 0.0f}, "left wing tip");
  expect_near(fin_top, {0.0f, 0.0f, -1.85f}, "fin top");
  EXPECT_NEAR(glm::determinant(b), 1.0f, 1e-6);  // a rotation: no mirror, no scale
}

TEST(EntityModels, DefaultTable) {
  const ModelTable table = load_model_table(kModels + "default_models.json");
  ASSERT_EQ(table.entities.size(), 3u);
  const char* expected[] = {"aircraft.glb", "ground_vehicle.glb", "ship.glb"};
  for (std::uint16_t type = 1; type <= 3; ++type) {
    const EntityModels* e = table.find(type);
    ASSERT_NE(e, nullptr) << "type " << type;
    ASSERT_EQ(e->lods.size(), 3u);
    EXPECT_NE(e->lods[0].file.find(expected[type - 1]), std::string::npos) << e->lods[0].file;
    const ModelLoad fine = load_model(e->lods[0].file), coarse = load_model(e->lods[1].file),
                    far = load_model(e->lods[2].file);
    ASSERT_TRUE(fine.ok() && coarse.ok() && far.ok()) << fine.error << coarse.error << far.error;
    EXPECT_LT(coarse.model->triangles, fine.model->triangles);
    EXPECT_EQ(far.model->triangles, 12u);  // one box
    // The far box spans the fine model's extent, within a metre.
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(far.model->bounds.min[a], fine.model->bounds.min[a], 1.0) << e->name << " axis " << a;
      EXPECT_NEAR(far.model->bounds.max[a], fine.model->bounds.max[a], 1.0) << e->name << " axis " << a;
    }
    EXPECT_EQ(choose_lod(*e, 1000.0), 0);
    EXPECT_EQ(choose_lod(*e, 20.0), 1);
    EXPECT_EQ(choose_lod(*e, 0.5), 2);  // the far box goes down to 0 px: traffic never vanishes for size
  }
  EXPECT_EQ(table.find(4), nullptr);
  EXPECT_GT(table.default_box_m.x, 0.0f);
}

}  // namespace
