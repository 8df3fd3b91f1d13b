// make_entity_models OUT_DIR: writes the project's entity models
// (models/tools/entity_shapes.h) into OUT_DIR as glTF binaries, with
// TinyGLTF's writer (Debian's build has it, and stb_image_write for the
// embedded PNG texture). Run by the build (visual/CMakeLists.txt); no input
// but the code, so the files are the same on every build.

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

#include <tiny_gltf.h>

#include "models/tools/entity_designs.h"
#include "models/tools/entity_shapes.h"

namespace {

using namespace ig::models;

// Appends `bytes` to buffer 0 (4-byte aligned, as accessors need) as a new
// buffer view; returns its index.
int add_view(tinygltf::Model& g, const void* bytes, std::size_t size, int target) {
  std::vector<unsigned char>& data = g.buffers[0].data;
  while (data.size() % 4 != 0) data.push_back(0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = size;
  view.target = target;
  const auto* p = static_cast<const unsigned char*>(bytes);
  data.insert(data.end(), p, p + size);
  g.bufferViews.push_back(view);
  return int(g.bufferViews.size() - 1);
}

template <typename V>
int add_accessor(tinygltf::Model& g, const std::vector<V>& values, int type, int target, bool with_bounds) {
  tinygltf::Accessor a;
  a.bufferView = add_view(g, values.data(), values.size() * sizeof(V), target);
  a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  a.count = values.size();
  a.type = type;
  if (with_bounds) {  // glTF requires min and max on POSITION
    const int n = int(sizeof(V) / sizeof(float));
    a.minValues.assign(std::size_t(n), 1e30);
    a.maxValues.assign(std::size_t(n), -1e30);
    for (const V& v : values) {
      for (int k = 0; k < n; ++k) {
        a.minValues[std::size_t(k)] = std::min(a.minValues[std::size_t(k)], double(v[k]));
        a.maxValues[std::size_t(k)] = std::max(a.maxValues[std::size_t(k)], double(v[k]));
      }
    }
  }
  g.accessors.push_back(a);
  return int(g.accessors.size() - 1);
}

int add_indices(tinygltf::Model& g, const std::vector<std::uint32_t>& idx, std::size_t vertices) {
  tinygltf::Accessor a;
  a.count = idx.size();
  a.type = TINYGLTF_TYPE_SCALAR;
  if (vertices <= 65535) {  // 16-bit where they fit, as exporters do
    std::vector<std::uint16_t> small(idx.begin(), idx.end());
    a.bufferView = add_view(g, small.data(), small.size() * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  } else {
    a.bufferView = add_view(g, idx.data(), idx.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  }
  g.accessors.push_back(a);
  return int(g.accessors.size() - 1);
}

tinygltf::Model to_gltf(const shapes::EntityModel& e) {
  tinygltf::Model g;
  g.asset.version = "2.0";
  g.asset.generator = "ig make_entity_models";
  g.buffers.emplace_back();
  if (e.texture) {
    tinygltf::Image image;
    image.name = e.texture->name;
    image.width = e.texture->width;
    image.height = e.texture->height;
    image.component = 4;
    image.bits = 8;
    image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image.image = e.texture->rgba;
    image.mimeType = "image/png";  // embedded as a PNG data URI by the writer
    g.images.push_back(image);
    tinygltf::Sampler sampler;
    sampler.wrapS = TINYGLTF_TEXTURE_WRAP_REPEAT;  // round the fuselage
    sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
    sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
    sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    g.samplers.push_back(sampler);
    tinygltf::Texture texture;
    texture.source = 0;
    texture.sampler = 0;
    g.textures.push_back(texture);
  }
  for (const shapes::MaterialData& m : e.materials) {
    tinygltf::Material mat;
    mat.name = m.name;
    mat.pbrMetallicRoughness.baseColorFactor = {m.base_color.r, m.base_color.g, m.base_color.b, m.base_color.a};
    mat.pbrMetallicRoughness.metallicFactor = 0.0;
    mat.pbrMetallicRoughness.roughnessFactor = 0.8;
    if (m.textured && e.texture) mat.pbrMetallicRoughness.baseColorTexture.index = 0;
    mat.alphaMode = m.blend ? "BLEND" : "OPAQUE";
    mat.doubleSided = m.double_sided;
    g.materials.push_back(mat);
  }
  for (const shapes::MeshData& m : e.meshes) {
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.material = m.material;
    prim.attributes["POSITION"] = add_accessor(g, m.positions, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
    prim.attributes["NORMAL"] = add_accessor(g, m.normals, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
    if (e.materials[std::size_t(m.material)].textured && e.texture) {
      prim.attributes["TEXCOORD_0"] =
          add_accessor(g, m.texcoords, TINYGLTF_TYPE_VEC2, TINYGLTF_TARGET_ARRAY_BUFFER, false);
    }
    prim.indices = add_indices(g, m.indices, m.positions.size());
    tinygltf::Mesh mesh;
    mesh.name = m.name;
    mesh.primitives.push_back(prim);
    g.meshes.push_back(mesh);
  }
  for (const shapes::NodeData& n : e.nodes) {
    tinygltf::Node node;
    node.name = n.name;
    node.mesh = n.mesh;
    if (n.translation != glm::vec3(0.0f)) node.translation = {n.translation.x, n.translation.y, n.translation.z};
    g.nodes.push_back(node);
  }
  for (std::size_t i = 0; i < e.nodes.size(); ++i) {
    if (e.nodes[i].parent >= 0) g.nodes[std::size_t(e.nodes[i].parent)].children.push_back(int(i));
  }
  tinygltf::Scene scene;
  scene.name = e.nodes[0].name;
  scene.nodes = {0};
  g.scenes.push_back(scene);
  g.defaultScene = 0;
  g.buffers[0].data.resize((g.buffers[0].data.size() + 3) / 4 * 4, 0);
  return g;
}

}  // namespace

glm::vec3 vec(const std::array<float, 3>& a) { return {a[0], a[1], a[2]}; }

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_entity_models OUT_DIR\n");
    return 2;
  }
  const std::filesystem::path out = argv[1];
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec) {
    std::fprintf(stderr, "make_entity_models: cannot create %s: %s\n", out.c_str(), ec.message().c_str());
    return 1;
  }
  using designs::Detail;
  struct Job {
    shapes::EntityModel model;
    std::uint64_t designed;
  };
  const Job jobs[] = {
      {shapes::build_aircraft(Detail::Fine), designs::aircraft_triangles(Detail::Fine)},
      {shapes::build_aircraft(Detail::Coarse), designs::aircraft_triangles(Detail::Coarse)},
      {shapes::build_ground_vehicle(Detail::Fine), designs::vehicle_triangles(Detail::Fine)},
      {shapes::build_ground_vehicle(Detail::Coarse), designs::vehicle_triangles(Detail::Coarse)},
      {shapes::build_ship(Detail::Fine), designs::ship_triangles(Detail::Fine)},
      {shapes::build_ship(Detail::Coarse), designs::ship_triangles(Detail::Coarse)},
      // One box over each design's extent (glTF axes), in its main colour.
      {shapes::build_far("aircraft_far.glb", vec(designs::kAircraftBounds.min), vec(designs::kAircraftBounds.max),
                         {0.92f, 0.92f, 0.95f, 1.0f}), 12},
      {shapes::build_far("ground_vehicle_far.glb", vec(designs::kVehicleBounds.min), vec(designs::kVehicleBounds.max),
                         {0.30f, 0.36f, 0.18f, 1.0f}), 12},
      {shapes::build_far("ship_far.glb", vec(designs::kShipBounds.min), vec(designs::kShipBounds.max),
                         {0.45f, 0.47f, 0.50f, 1.0f}), 12},
  };
  for (const Job& job : jobs) {
    // The builder must make what the design says, or the tests' figures lie.
    if (job.model.triangles() != job.designed) {
      std::fprintf(stderr, "make_entity_models: %s has %llu triangles, the design says %llu\n",
                   job.model.file.c_str(), (unsigned long long)job.model.triangles(),
                   (unsigned long long)job.designed);
      return 1;
    }
    const tinygltf::Model gltf = to_gltf(job.model);
    const std::string path = (out / job.model.file).string();
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&gltf, path, /*embedImages=*/true, /*embedBuffers=*/true, /*prettyPrint=*/false,
                                     /*writeBinary=*/true)) {
      std::fprintf(stderr, "make_entity_models: cannot write %s\n", path.c_str());
      return 1;
    }
    std::printf("%s: %llu triangles\n", path.c_str(), (unsigned long long)job.model.triangles());
  }
  return 0;
}
