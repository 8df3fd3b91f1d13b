// What the loader makes of valid glTF: strips and fans as triangle lists
// with the file's winding, flat normals where the file has none, unused
// vertices dropped, instancing counted, node transforms composed into the
// bounds, and the accessor forms exporters use (interleaved views, sparse
// accessors, quantized and normalized attributes).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include <glm/geometric.hpp>

#include "models/test/gltf_test_files.h"

namespace {

using namespace ig::models;
using namespace ig::models::test;

class Loader : public ModelFilesTest {};

// A real PNG for texture tests: the aircraft's livery, as the data URI
// make_entity_models embedded in aircraft.glb's JSON.
std::string livery_png_data_uri() {
  std::ifstream in(std::string(IG_BIN_DIR) + "/models/aircraft.glb", std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
  if (bytes.size() < 20) return "";
  std::uint32_t json_len = 0;
  std::memcpy(&json_len, bytes.data() + 12, 4);
  const json doc = json::parse(bytes.begin() + 20, bytes.begin() + 20 + json_len);
  return doc.at("images").at(0).at("uri").get<std::string>();
}

// Every triangle's right-hand normal, for winding checks.
std::vector<glm::vec3> face_normals(const Primitive& p) {
  std::vector<glm::vec3> out;
  for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
    const glm::vec3 a = p.positions[p.indices[t]], b = p.positions[p.indices[t + 1]], c = p.positions[p.indices[t + 2]];
    out.push_back(glm::normalize(glm::cross(b - a, c - a)));
  }
  return out;
}

// Four points of a unit square in z = 0, counter-clockwise seen from +Z,
// in the order a strip wants them (0 1 / 2 3 zig-zag) or a fan (round).
const std::vector<float> kStripSquare = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
const std::vector<float> kFanSquare = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};

TEST_F(Loader, StripsAndFansBecomeListsWithTheFilesWinding) {
  for (const int mode : {kStrip, kFan}) {
    GltfBuilder b;
    const int pos = b.add_floats(mode == kStrip ? kStripSquare : kFanSquare, "VEC3");
    b.set_scene({b.add_node("quad", b.add_mesh(pos, -1, mode))});
    const ModelLoad r = expect_loaded(write_gltf("quad", b));
    ASSERT_TRUE(r.ok());
    const Primitive& p = r.model->meshes.at(0).primitives.at(0);
    ASSERT_EQ(p.triangle_count(), 2u) << "mode " << mode;
    for (const glm::vec3& n : face_normals(p)) EXPECT_NEAR(n.z, 1.0f, 1e-6) << "mode " << mode;  // both face +Z
    // Flat normals computed (the file has none) agree with the winding.
    for (const glm::vec3& n : p.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
    EXPECT_NEAR(r.model->bounds.radius, std::sqrt(0.5f), 1e-5);
  }
}

// A strip's degenerate triangles (repeated indices stitching two strips)
// are dropped.
TEST_F(Loader, DegenerateStripTrianglesDropped) {
  GltfBuilder b;
  const int pos = b.add_floats(kStripSquare, "VEC3");
  const int idx = b.add_indices({0, 1, 2, 3, 3, 0, 0, 1, 2});  // strip, stitch, strip again
  b.set_scene({b.add_node("s", b.add_mesh(pos, idx, kStrip))});
  const ModelLoad r = expect_loaded(write_gltf("stitched", b));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.model->triangles, 3u);  // 2 + 1 real, 4 degenerate dropped
}

TEST_F(Loader, FileNormalsNormalisedAndSharedVerticesKept) {
  GltfBuilder b;
  const int pos = b.add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 9, 9, 9}, "VEC3");  // vertex 3 unused
  const int nrm = b.add_floats({0, 0, 2, 0, 0, 3, 0, 0.6f, 0.8f, 1, 0, 0}, "VEC3");
  b.set_scene({b.add_node("n", b.add_mesh(pos, b.add_indices({0, 1, 2})))});
  b.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = nrm;
  const ModelLoad r = expect_loaded(write_gltf("normals", b));
  ASSERT_TRUE(r.ok());
  const Primitive& p = r.model->meshes.at(0).primitives.at(0);
  ASSERT_EQ(p.positions.size(), 3u);  // the unused vertex is gone
  EXPECT_EQ(p.normals[0], glm::vec3(0, 0, 1));
  EXPECT_EQ(p.normals[1], glm::vec3(0, 0, 1));
  EXPECT_NEAR(glm::length(p.normals[2] - glm::vec3(0, 0.6f, 0.8f)), 0.0f, 1e-6);
  // It does not stretch the bounds either.
  EXPECT_EQ(r.model->bounds.max, glm::vec3(1, 1, 0));
}

// Transforms: translation, rotation (x, y, z, w) and scale per node,
// composed down the hierarchy, in the bounds and in node_to_model.
TEST_F(Loader, NodeTransformsComposeIntoTheBounds) {
  GltfBuilder b;
  b.one_triangle();  // node 0 "tri": (0,0,0) (1,0,0) (0,1,0)
  const float s = std::sqrt(0.5f);
  b.doc["nodes"][0]["rotation"] = {0.0, 0.0, s, s};  // +90 degrees about Z: (1,0,0) -> (0,1,0)
  b.doc["nodes"][0]["scale"] = {2.0, 2.0, 2.0};
  const int parent = b.add_node("parent", -1, {0});
  b.doc["nodes"][std::size_t(parent)]["translation"] = {10.0, 0.0, -5.0};
  b.set_scene({parent});
  const ModelLoad r = expect_loaded(write_gltf("trs", b));
  ASSERT_TRUE(r.ok());
  const Model& m = *r.model;
  ASSERT_EQ(m.nodes.size(), 2u);
  EXPECT_EQ(m.nodes[0].name, "parent");  // parents first
  EXPECT_EQ(m.nodes[1].parent, 0);
  // Scaled by 2 then turned: (2,0,0) -> (0,2,0), (0,2,0) -> (-2,0,0); then moved.
  EXPECT_NEAR(glm::length(m.bounds.min - glm::vec3(8, 0, -5)), 0.0f, 1e-5);
  EXPECT_NEAR(glm::length(m.bounds.max - glm::vec3(10, 2, -5)), 0.0f, 1e-5);
  const glm::vec4 tip = m.node_to_model()[1] * glm::vec4(1, 0, 0, 1);
  EXPECT_NEAR(glm::length(glm::vec3(tip) - glm::vec3(10, 2, -5)), 0.0f, 1e-5);
  // A matrix instead of TRS (column-major, as glTF writes it).
  GltfBuilder c;
  c.one_triangle();
  c.doc["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 3, 4, 5, 1};
  const ModelLoad rm = expect_loaded(write_gltf("matrix", c));
  ASSERT_TRUE(rm.ok());
  EXPECT_EQ(rm.model->bounds.min, glm::vec3(3, 4, 5));
}

// One mesh drawn by three nodes counts three times; bounds cover each copy.
TEST_F(Loader, InstancingCounted) {
  GltfBuilder b;
  b.one_triangle();
  const int mesh = 0;
  std::vector<int> copies;
  for (int i = 0; i < 3; ++i) {
    copies.push_back(b.add_node("copy" + std::to_string(i), mesh));
    b.doc["nodes"][std::size_t(copies.back())]["translation"] = {0.0, 0.0, double(i) * 10.0};
  }
  b.set_scene({0, copies[0], copies[1], copies[2]});
  const ModelLoad r = expect_loaded(write_gltf("instances", b));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.model->meshes.size(), 1u);
  EXPECT_EQ(r.model->triangles, 4u);
  EXPECT_EQ(r.model->mesh_instances(), std::vector<std::uint32_t>{4});
  EXPECT_EQ(r.model->bounds.max.z, 20.0f);
  EXPECT_EQ(r.model->node_index("copy2"), 3);
  EXPECT_EQ(r.model->node_index("nobody"), -1);
}

// Position and normal interleaved in one view (stride 24 bytes).
TEST_F(Loader, InterleavedView) {
  GltfBuilder b;
  const std::vector<float> interleaved = {0, 0, 0, 0, 0, 1, 4, 0, 0, 0, 0, 1, 0, 4, 0, 0, 0, 1};
  const int view = b.add_view(interleaved.data(), interleaved.size() * 4, 24);
  const int pos = b.add_accessor(view, kFloat, 3, "VEC3", 0);
  const int nrm = b.add_accessor(view, kFloat, 3, "VEC3", 12);
  b.set_scene({b.add_node("i", b.add_mesh(pos, -1))});
  b.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = nrm;
  const ModelLoad r = expect_loaded(write_gltf("interleaved", b));
  ASSERT_TRUE(r.ok());
  const Primitive& p = r.model->meshes.at(0).primitives.at(0);
  EXPECT_EQ(p.positions, (std::vector<glm::vec3>{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}));
  EXPECT_EQ(p.normals, (std::vector<glm::vec3>(3, glm::vec3(0, 0, 1))));
}

// A sparse accessor: a base of zeros (no bufferView) with two vertices
// substituted, and one over a real base.
TEST_F(Loader, SparseAccessor) {
  GltfBuilder b;
  const std::vector<std::uint16_t> which = {1, 2};
  const std::vector<float> values = {5, 0, 0, 0, 5, 0};
  const int idx_view = b.add_view(which.data(), 4);
  const int val_view = b.add_view(values.data(), values.size() * 4);
  const int pos = b.add_accessor(-1, kFloat, 3, "VEC3");
  b.doc["accessors"][std::size_t(pos)]["sparse"] = {
      {"count", 2}, {"indices", {{"bufferView", idx_view}, {"componentType", kUShort}}}, {"values", {{"bufferView", val_view}}}};
  b.set_scene({b.add_node("s", b.add_mesh(pos, -1))});
  const ModelLoad r = expect_loaded(write_gltf("sparse", b));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.model->meshes[0].primitives[0].positions, (std::vector<glm::vec3>{{0, 0, 0}, {5, 0, 0}, {0, 5, 0}}));
  // A sparse index past the accessor is refused.
  const std::vector<std::uint16_t> bad = {1, 3};
  b.doc["bufferViews"][std::size_t(idx_view)]["byteOffset"] = b.bin.size();
  b.add_view(bad.data(), 4);
  expect_refused(write_gltf("sparse_bad", b), {"sparse index 3 is out of range (3 elements)"});
}

// Quantized attributes (KHR_mesh_quantization): 16-bit positions, 8-bit
// normalized normals and texture coordinates.
TEST_F(Loader, QuantizedAttributes) {
  GltfBuilder b;
  const std::vector<std::int16_t> pos = {0, 0, 0, 0, 100, 0, 0, 0, 0, 100, 0, 0};  // padded to 4-byte elements
  const std::vector<std::int8_t> nrm = {0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127, 0};
  const std::vector<std::uint8_t> uv = {0, 0, 255, 0, 0, 255};
  const int p = b.add_accessor(b.add_view(pos.data(), pos.size() * 2, 8), 5122, 3, "VEC3");
  const int n = b.add_accessor(b.add_view(nrm.data(), nrm.size(), 4), 5120, 3, "VEC3");
  const int t = b.add_accessor(b.add_view(uv.data(), uv.size()), kUByte, 3, "VEC2");
  b.doc["accessors"][std::size_t(n)]["normalized"] = true;
  b.doc["accessors"][std::size_t(t)]["normalized"] = true;
  b.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
  b.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
  b.doc["images"] = json::array({{{"uri", livery_png_data_uri()}}});
  b.doc["textures"] = json::array({{{"source", 0}}});
  b.doc["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
  b.set_scene({b.add_node("q", b.add_mesh(p, -1, kTriangles, 0))});
  b.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = n;
  b.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = t;
  const ModelLoad r = expect_loaded(write_gltf("quantized", b));
  ASSERT_TRUE(r.ok());
  const Primitive& prim = r.model->meshes[0].primitives[0];
  EXPECT_EQ(prim.positions, (std::vector<glm::vec3>{{0, 0, 0}, {100, 0, 0}, {0, 100, 0}}));
  EXPECT_EQ(prim.normals, (std::vector<glm::vec3>(3, glm::vec3(0, 0, 1))));
  EXPECT_EQ(prim.texcoords, (std::vector<glm::vec2>{{0, 0}, {1, 0}, {0, 1}}));
  ASSERT_EQ(r.model->images.size(), 1u);
  EXPECT_EQ(r.model->images[0].width, 64);
  // Without a usable image the texture coordinates are not kept: the
  // material has no texture to use them with.
  b.doc["images"][0]["uri"] = "absent.png";
  const ModelLoad untextured = expect_loaded(write_gltf("quantized", b));
  ASSERT_TRUE(untextured.ok());
  EXPECT_TRUE(untextured.model->meshes[0].primitives[0].texcoords.empty());
}

// Scenes: the default one, not the first; nodes outside it are not drawn.
TEST_F(Loader, DefaultSceneChosen) {
  GltfBuilder b;
  b.one_triangle();                                  // node 0, in scene 0 only
  const int other = b.add_node("other", 0);           // node 1, in scene 1
  b.doc["nodes"][std::size_t(other)]["translation"] = {100.0, 0.0, 0.0};
  b.doc["scenes"] = json::array({{{"nodes", {0}}}, {{"nodes", {other}}}});
  b.doc["scene"] = 1;
  const ModelLoad r = expect_loaded(write_gltf("scenes", b));
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.model->nodes.size(), 1u);
  EXPECT_EQ(r.model->nodes[0].name, "other");
  EXPECT_EQ(r.model->bounds.min.x, 100.0f);
  EXPECT_TRUE(r.warnings.empty());
}

TEST_F(Loader, MaterialsConverted) {
  GltfBuilder b;
  b.one_triangle();
  b.doc["materials"] = json::array(
      {{{"name", "glass"}, {"alphaMode", "BLEND"}, {"doubleSided", true},
        {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.3, 2.0, 0.4}}}}},
       {{"name", "leaves"}, {"alphaMode", "MASK"}, {"alphaCutoff", 0.25}, {"extensions", {{"KHR_materials_unlit", json::object()}}}},
       {{"name", "odd"}, {"alphaMode", "SHINY"}}});
  b.doc["meshes"][0]["primitives"][0]["material"] = 7;  // does not exist
  const ModelLoad r = expect_loaded(write_gltf("materials", b));
  ASSERT_TRUE(r.ok());
  const auto& mats = r.model->materials;
  ASSERT_EQ(mats.size(), 3u);
  EXPECT_EQ(mats[0].alpha_mode, AlphaMode::Blend);
  EXPECT_TRUE(mats[0].double_sided);
  EXPECT_EQ(mats[0].base_color, glm::vec4(0.2f, 0.3f, 1.0f, 0.4f));  // clamped to [0, 1]
  EXPECT_EQ(mats[1].alpha_mode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(mats[1].alpha_cutoff, 0.25f);
  EXPECT_TRUE(mats[1].unlit);
  EXPECT_EQ(mats[2].alpha_mode, AlphaMode::Opaque);
  EXPECT_TRUE(any_warning(r, {"material 2 ('odd')", "alphaMode \"SHINY\""}));
  EXPECT_TRUE(any_warning(r, {"material 7 does not exist"}));
  EXPECT_EQ(r.model->meshes[0].primitives[0].material, -1);
  EXPECT_STREQ(alpha_mode_name(AlphaMode::Mask), "mask");
}

// The same triangle as .gltf and as .glb gives the same model.
TEST_F(Loader, GltfAndGlbAgree) {
  GltfBuilder b;
  b.one_triangle();
  const ModelLoad text = expect_loaded(write_gltf("tri", b));
  const ModelLoad binary = expect_loaded(write("tri.glb", b.glb()));
  ASSERT_TRUE(text.ok() && binary.ok());
  EXPECT_EQ(text.model->meshes[0].primitives[0].positions, binary.model->meshes[0].primitives[0].positions);
  EXPECT_EQ(text.model->triangles, binary.model->triangles);
  // A .glb named .gltf is still read as binary: the magic decides.
  const ModelLoad misnamed = expect_loaded(write("really_binary.gltf", b.glb()));
  EXPECT_TRUE(misnamed.ok());
}

}  // namespace
