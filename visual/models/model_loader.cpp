#include "models/model_loader.h"

#include <map>

#include "models/gltf_reader.h"
#include "models/material_converter.h"
#include "models/model_bounds.h"
#include "models/model_error.h"
#include "models/node_graph.h"
#include "models/primitive_builder.h"

namespace ig::models {

namespace {

std::uint64_t saturating_mul(std::uint64_t a, std::uint64_t b) {
  if (a != 0 && b > UINT64_MAX / a) return UINT64_MAX;
  return a * b;
}

std::string primitive_name(const tinygltf::Model& gltf, int mesh, std::size_t p) {
  return describe("mesh", std::size_t(mesh), gltf.meshes[std::size_t(mesh)].name) + " primitive " + std::to_string(p);
}

// Refuses a model above the triangle cap from its accessors' counts alone,
// before any vertex is read (a small file instancing one mesh ten million
// times costs nothing to refuse).
void check_triangle_cap(const tinygltf::Model& gltf, const std::vector<int>& used_meshes,
                        const std::map<int, std::uint64_t>& instances, const ModelLimits& limits) {
  std::uint64_t total = 0, worst = 0;
  int worst_mesh = -1;
  std::uint64_t worst_tris = 0;
  for (int m : used_meshes) {
    std::uint64_t tris = 0;
    const auto& prims = gltf.meshes[std::size_t(m)].primitives;
    for (std::size_t p = 0; p < prims.size(); ++p) {
      tris += primitive_triangle_bound(gltf, prims[p], primitive_name(gltf, m, p));
    }
    const std::uint64_t drawn = saturating_mul(tris, instances.at(m));
    total = drawn > UINT64_MAX - total ? UINT64_MAX : total + drawn;
    if (drawn > worst) {
      worst = drawn;
      worst_mesh = m;
      worst_tris = tris;
    }
  }
  if (total <= limits.max_triangles) return;
  throw ModelError(std::to_string(total) + " triangles counting instancing, above the cap of " +
                   std::to_string(limits.max_triangles) + " (most from " +
                   describe("mesh", std::size_t(worst_mesh), gltf.meshes[std::size_t(worst_mesh)].name) + ": " +
                   std::to_string(worst_tris) + " triangles drawn by " + std::to_string(instances.at(worst_mesh)) +
                   (instances.at(worst_mesh) == 1 ? " node)" : " nodes)"));
}

Model convert(const GltfDocument& doc, const ModelLimits& limits, std::vector<std::string>& warnings) {
  const tinygltf::Model& gltf = doc.gltf;
  const SceneNodes scene = scene_nodes(gltf, warnings);

  // The meshes the scene draws, in order of first use, and how many times.
  std::vector<int> used_meshes;
  std::map<int, std::uint64_t> instances;
  std::vector<int> node_mesh(scene.source.size(), -1);  // glTF mesh per drawn node
  bool skinned = false;
  for (std::size_t i = 0; i < scene.source.size(); ++i) {
    const tinygltf::Node& node = gltf.nodes[std::size_t(scene.source[i])];
    skinned |= node.skin >= 0;
    if (node.mesh < 0) continue;
    if (std::size_t(node.mesh) >= gltf.meshes.size()) {
      warnings.push_back(describe("node", std::size_t(scene.source[i]), node.name) + " refers to mesh " +
                         std::to_string(node.mesh) + ", which does not exist: drawn without it");
      continue;
    }
    if (instances[node.mesh]++ == 0) used_meshes.push_back(node.mesh);
    node_mesh[i] = node.mesh;
  }
  check_triangle_cap(gltf, used_meshes, instances, limits);

  ConvertedMaterials mats = convert_materials(gltf, doc.image_failures, warnings);

  Model model;
  std::map<int, int> mesh_slot;  // glTF mesh -> Model::meshes index
  bool morphed = false;
  std::size_t primitives = 0, skipped = 0;
  for (int m : used_meshes) {
    const tinygltf::Mesh& gm = gltf.meshes[std::size_t(m)];
    Mesh mesh;
    mesh.name = gm.name;
    for (std::size_t p = 0; p < gm.primitives.size(); ++p) {
      const tinygltf::Primitive& prim = gm.primitives[p];
      const std::string what = primitive_name(gltf, m, p);
      morphed |= !prim.targets.empty();
      int material = prim.material;
      if (material >= int(mats.materials.size())) {
        warnings.push_back(what + ": material " + std::to_string(material) +
                           " does not exist: the default material used");
        material = -1;
      }
      const int set = material >= 0 ? mats.texcoord_set[std::size_t(material)] : -1;
      std::optional<Primitive> built = build_primitive(gltf, prim, what, set, limits, warnings);
      ++primitives;
      if (!built) {
        ++skipped;
        continue;
      }
      built->material = material < 0 ? -1 : material;
      mesh.primitives.push_back(std::move(*built));
    }
    mesh_slot[m] = int(model.meshes.size());
    model.meshes.push_back(std::move(mesh));
  }

  model.materials = std::move(mats.materials);
  model.images = std::move(mats.images);
  for (std::size_t i = 0; i < scene.source.size(); ++i) {
    Node node;
    node.name = gltf.nodes[std::size_t(scene.source[i])].name;
    node.parent = scene.parent[i];
    node.local = scene.local[i];
    node.mesh = node_mesh[i] >= 0 ? mesh_slot.at(node_mesh[i]) : -1;
    if (node.mesh >= 0) model.triangles += model.meshes[std::size_t(node.mesh)].triangle_count();
    model.nodes.push_back(std::move(node));
  }
  if (model.triangles == 0) {
    throw ModelError("nothing to draw: no triangles in the scene (" + std::to_string(model.nodes.size()) +
                     " nodes, " + std::to_string(model.meshes.size()) + " meshes, " + std::to_string(primitives) +
                     " primitives, " + std::to_string(skipped) + " of them points, lines or empty)");
  }
  const std::optional<Bounds> bounds = compute_bounds(model);
  if (!bounds) throw ModelError("the model's extent is not finite (node transforms scale it beyond float range)");
  model.bounds = *bounds;

  if (skinned) warnings.push_back("skins ignored: skinned meshes are drawn in their bind pose");
  if (morphed) warnings.push_back("morph targets ignored: meshes are drawn in their base shape");
  if (!gltf.animations.empty()) {
    warnings.push_back(std::to_string(gltf.animations.size()) +
                       " animations ignored: the IG moves named nodes itself");
  }
  return model;
}

}  // namespace

ModelLoad load_model(const std::string& path, const ModelLimits& limits) {
  ModelLoad result;
  std::vector<std::string> warnings;
  try {
    const GltfDocument doc = read_gltf(path, limits, warnings);
    Model model = convert(doc, limits, warnings);
    model.source = path;
    result.model = std::move(model);
  } catch (const ModelError& e) {
    result.error = path + ": " + e.what();
  } catch (const std::bad_alloc&) {
    result.error = path + ": out of memory while loading";
  } catch (const std::exception& e) {
    result.error = path + ": " + e.what();
  }
  for (const std::string& w : warnings) result.warnings.push_back(path + ": " + w);
  return result;
}

}  // namespace ig::models
