#pragma once
// Writing glTF test files inside a test: a temporary folder per test, and
// a small builder for .gltf / .glb documents whose every field the test
// controls (so it can make them wrong on purpose).

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/model_loader.h"

namespace ig::models::test {

using json = nlohmann::json;

// glTF's numeric codes, spelt out for readability.
constexpr int kFloat = 5126, kUShort = 5123, kUInt = 5125, kUByte = 5121;
constexpr int kPoints = 0, kLines = 1, kTriangles = 4, kStrip = 5, kFan = 6;

// A glTF document and its binary buffer, built up piece by piece.
struct GltfBuilder {
  json doc = {{"asset", {{"version", "2.0"}}}};
  std::vector<std::uint8_t> bin;

  GltfBuilder() {
    for (const char* k : {"bufferViews", "accessors", "meshes", "nodes", "materials"}) doc[k] = json::array();
  }

  // Appends raw bytes (4-byte aligned) as a buffer view of buffer 0.
  int add_view(const void* bytes, std::size_t size, int stride = 0) {
    while (bin.size() % 4 != 0) bin.push_back(0);
    json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", size}};
    if (stride > 0) v["byteStride"] = stride;
    const auto* p = static_cast<const std::uint8_t*>(bytes);
    bin.insert(bin.end(), p, p + size);
    doc["bufferViews"].push_back(v);
    return int(doc["bufferViews"].size()) - 1;
  }
  int add_accessor(int view, int component_type, std::size_t count, const std::string& type,
                   std::size_t byte_offset = 0) {
    json a = {{"componentType", component_type}, {"count", count}, {"type", type}};
    if (view >= 0) a["bufferView"] = view;
    if (byte_offset > 0) a["byteOffset"] = byte_offset;
    doc["accessors"].push_back(a);
    return int(doc["accessors"].size()) - 1;
  }
  int add_floats(const std::vector<float>& v, const std::string& type) {
    const int comps = type == "VEC2" ? 2 : type == "VEC3" ? 3 : type == "VEC4" ? 4 : 1;
    return add_accessor(add_view(v.data(), v.size() * 4), kFloat, v.size() / std::size_t(comps), type);
  }
  int add_indices(const std::vector<std::uint32_t>& idx) {
    return add_accessor(add_view(idx.data(), idx.size() * 4), kUInt, idx.size(), "SCALAR");
  }
  // A mesh of one primitive; indices < 0: none.
  int add_mesh(int positions, int indices, int mode = kTriangles, int material = -1, const std::string& name = "") {
    json prim = {{"attributes", {{"POSITION", positions}}}, {"mode", mode}};
    if (indices >= 0) prim["indices"] = indices;
    if (material >= 0) prim["material"] = material;
    json mesh = {{"primitives", json::array({prim})}};
    if (!name.empty()) mesh["name"] = name;
    doc["meshes"].push_back(mesh);
    return int(doc["meshes"].size()) - 1;
  }
  int add_node(const std::string& name, int mesh = -1, std::vector<int> children = {}) {
    json n = json::object();
    if (!name.empty()) n["name"] = name;
    if (mesh >= 0) n["mesh"] = mesh;
    if (!children.empty()) n["children"] = children;
    doc["nodes"].push_back(n);
    return int(doc["nodes"].size()) - 1;
  }
  void set_scene(std::vector<int> roots) {
    doc["scenes"] = json::array({{{"nodes", roots}}});
    doc["scene"] = 0;
  }
  // One triangle in the z = 0 plane, counter-clockwise seen from +Z, drawn by
  // one node: the smallest valid model.
  void one_triangle() {
    const int pos = add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
    const int mesh = add_mesh(pos, add_indices({0, 1, 2}));
    set_scene({add_node("tri", mesh)});
  }

  // The document as .gltf text with its buffer in `bin_uri` (written by the
  // caller), or as a .glb with the buffer in its BIN chunk.
  std::string gltf_text(const std::string& bin_uri) const {
    json d = doc;
    d["buffers"] = json::array({{{"uri", bin_uri}, {"byteLength", bin.size()}}});
    return d.dump();
  }
  std::vector<std::uint8_t> glb() const {
    json d = doc;
    std::vector<std::uint8_t> payload = bin;
    while (payload.size() % 4 != 0) payload.push_back(0);
    if (!payload.empty()) d["buffers"] = json::array({{{"byteLength", bin.size()}}});
    return glb_bytes(d.dump(), payload);
  }

  // A GLB container around `json_text` and `payload` (no BIN chunk when empty).
  static std::vector<std::uint8_t> glb_bytes(std::string json_text, const std::vector<std::uint8_t>& payload) {
    while (json_text.size() % 4 != 0) json_text += ' ';
    std::vector<std::uint8_t> out;
    auto u32 = [&](std::uint32_t v) {
      for (int i = 0; i < 4; ++i) out.push_back(std::uint8_t(v >> (8 * i)));
    };
    const std::uint32_t total =
        std::uint32_t(12 + 8 + json_text.size() + (payload.empty() ? 0 : 8 + payload.size()));
    u32(0x46546C67);
    u32(2);
    u32(total);
    u32(std::uint32_t(json_text.size()));
    u32(0x4E4F534A);
    out.insert(out.end(), json_text.begin(), json_text.end());
    if (!payload.empty()) {
      u32(std::uint32_t(payload.size()));
      u32(0x004E4942);
      out.insert(out.end(), payload.begin(), payload.end());
    }
    return out;
  }
};

// A fresh temporary folder per test, removed afterwards.
class ModelFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("ig_models_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::string write(const std::string& name, const void* bytes, std::size_t size) const {
    std::ofstream out(path(name), std::ios::binary);
    out.write(static_cast<const char*>(bytes), std::streamsize(size));
    return path(name);
  }
  std::string write(const std::string& name, const std::string& text) const {
    return write(name, text.data(), text.size());
  }
  std::string write(const std::string& name, const std::vector<std::uint8_t>& bytes) const {
    return write(name, bytes.data(), bytes.size());
  }
  // `b` as name.gltf + name.bin.
  std::string write_gltf(const std::string& name, const GltfBuilder& b) const {
    write(name + ".bin", b.bin);
    return write(name + ".gltf", b.gltf_text(name + ".bin"));
  }

  // Loads `file`, which must be refused with a message naming the file and
  // containing every one of `parts`.
  static void expect_refused(const std::string& file, std::initializer_list<std::string> parts,
                             const ModelLimits& limits = {}) {
    const ModelLoad r = load_model(file, limits);
    ASSERT_FALSE(r.ok()) << file << " loaded, expected refusal";
    EXPECT_EQ(r.error.rfind(file + ": ", 0), 0u) << r.error;
    for (const std::string& p : parts) EXPECT_NE(r.error.find(p), std::string::npos) << "'" << p << "' not in: " << r.error;
  }
  // Loads `file`, which must load; returns it with its warnings.
  static ModelLoad expect_loaded(const std::string& file, const ModelLimits& limits = {}) {
    ModelLoad r = load_model(file, limits);
    EXPECT_TRUE(r.ok()) << r.error;
    return r;
  }
  static bool any_warning(const ModelLoad& r, std::initializer_list<std::string> parts) {
    for (const std::string& w : r.warnings) {
      bool all = true;
      for (const std::string& p : parts) all = all && w.find(p) != std::string::npos;
      if (all) return true;
    }
    return false;
  }

  std::filesystem::path dir_;
};

}  // namespace ig::models::test
