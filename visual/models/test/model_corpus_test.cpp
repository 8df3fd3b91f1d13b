// The public glTF corpus Debian ships (assimp-testmodels:
// /usr/share/assimp/models/glTF2, or $IG_GLTF_CORPUS_DIR): every .gltf and
// .glb either loads, with finite values only, or is refused with a reason
// naming the file. The corpus holds broken files on purpose (indices out of
// range, a node loop, a missing .bin, infinite positions, Draco); those must
// be refused for that cause. One line per file goes to stdout: the table in
// docs/models.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "models/model_loader.h"

namespace {

namespace fs = std::filesystem;
using namespace ig::models;

fs::path corpus_dir() {
  const char* env = std::getenv("IG_GLTF_CORPUS_DIR");
  return env && *env ? fs::path(env) : fs::path("/usr/share/assimp/models/glTF2");
}

std::vector<fs::path> corpus_files(const fs::path& dir) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    const std::string ext = it->path().extension().string();
    if (it->is_regular_file() && (ext == ".gltf" || ext == ".glb")) files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Everything a renderer would upload is finite and in range.
void expect_sane(const Model& m, const std::string& name) {
  EXPECT_GT(m.triangles, 0u) << name;
  EXPECT_TRUE(finite(m.bounds.min) && finite(m.bounds.max) && std::isfinite(m.bounds.radius)) << name;
  for (const Node& n : m.nodes) EXPECT_LT(n.mesh, int(m.meshes.size())) << name;
  for (const Mesh& mesh : m.meshes) {
    for (const Primitive& p : mesh.primitives) {
      ASSERT_EQ(p.normals.size(), p.positions.size()) << name;
      ASSERT_TRUE(p.texcoords.empty() || p.texcoords.size() == p.positions.size()) << name;
      for (std::size_t i = 0; i < p.positions.size(); ++i) {
        ASSERT_TRUE(finite(p.positions[i]) && finite(p.normals[i])) << name << " vertex " << i;
        ASSERT_NEAR(glm::length(p.normals[i]), 1.0f, 1e-3f) << name << " vertex " << i;
      }
      for (std::uint32_t i : p.indices) ASSERT_LT(i, p.positions.size()) << name;
      EXPECT_LT(p.material, int(m.materials.size())) << name;
    }
  }
  for (const Image& img : m.images) {
    EXPECT_EQ(img.rgba.size(), std::size_t(img.width) * std::size_t(img.height) * 4) << name;
  }
}

TEST(GltfCorpus, EveryFileLoadsOrIsRefusedWithAReason) {
  const fs::path dir = corpus_dir();
  if (!fs::is_directory(dir)) {
    GTEST_SKIP() << dir << " not found: install Debian's assimp-testmodels (tools/setup.sh) or set IG_GLTF_CORPUS_DIR";
  }
  const std::vector<fs::path> files = corpus_files(dir);
  ASSERT_FALSE(files.empty()) << "no .gltf or .glb under " << dir;

  std::map<std::string, ModelLoad> results;  // by path relative to the corpus
  int loaded = 0, refused = 0;
  for (const fs::path& f : files) {
    const std::string rel = fs::relative(f, dir).string();
    ModelLoad r = load_model(f.string());
    if (r.ok()) {
      ++loaded;
      expect_sane(*r.model, rel);
      std::cout << "| " << rel << " | loaded: " << r.model->triangles << " triangles";
      if (!r.warnings.empty()) std::cout << " (" << r.warnings.size() << " warnings)";
      std::cout << " |\n";
    } else {
      ++refused;
      EXPECT_EQ(r.error.rfind(f.string() + ": ", 0), 0u) << r.error;
      EXPECT_GT(r.error.size(), f.string().size() + 2) << rel << ": empty reason";
      std::cout << "| " << rel << " | refused: " << r.error.substr(f.string().size() + 2) << " |\n";
    }
    results.emplace(rel, std::move(r));
  }
  std::cout << files.size() << " files: " << loaded << " loaded, " << refused << " refused\n";

  // The known cases, where Debian's corpus has them (another corpus skips these).
  auto refused_for = [&](const std::string& rel, const std::string& cause) {
    const auto it = results.find(rel);
    if (it == results.end()) return;
    EXPECT_FALSE(it->second.ok()) << rel << " loaded";
    EXPECT_NE(it->second.error.find(cause), std::string::npos) << rel << ": " << it->second.error;
  };
  auto loaded_with = [&](const std::string& rel, std::uint64_t triangles) {
    const auto it = results.find(rel);
    if (it == results.end()) return;
    ASSERT_TRUE(it->second.ok()) << rel << ": " << it->second.error;
    EXPECT_EQ(it->second.model->triangles, triangles) << rel;
  };
  refused_for("draco/2CylinderEngine.gltf", "KHR_draco_mesh_compression");
  refused_for("BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf", "KHR_technique_webgl");
  refused_for("IndexOutOfRange/IndexOutOfRange.gltf", "out of range");
  refused_for("IndexOutOfRange/AllIndicesOutOfRange.gltf", "out of range");
  refused_for("RecursiveNodes/RecursiveNodes.gltf", "node hierarchy loop");
  refused_for("MissingBin/BoxTextured.gltf", "BoxTextured0.bin");
  refused_for("BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "NaN or infinite");
  refused_for("glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_00.gltf", "nothing to draw");
  loaded_with("BoxTextured-glTF/BoxTextured.gltf", 12);
  loaded_with("BoxTextured-glTF-Binary/BoxTextured.glb", 12);
  // Strips and fans arrive as lists: Mesh_PrimitiveMode_04 is a strip, _05 a
  // fan, each a quad of two triangles.
  loaded_with("glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_04.gltf", 2);
  loaded_with("glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_05.gltf", 2);
  // The textured box's texture decodes (CesiumLogoFlat.png, 211 x 211).
  const auto box = results.find("BoxTextured-glTF/BoxTextured.gltf");
  if (box != results.end() && box->second.ok()) {
    ASSERT_EQ(box->second.model->images.size(), 1u);
    EXPECT_EQ(box->second.model->images[0].width, 211);
    EXPECT_EQ(box->second.model->materials.at(0).base_color_image, 0);
  }
}

}  // namespace
