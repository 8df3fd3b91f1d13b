#pragma once
// The caps a model must stay under to be loaded. They bound the memory and
// time a hostile or careless file can cost the IG: every one is checked
// from the file's declared sizes before anything that big is allocated.

#include <cstdint>

namespace ig::models {

struct ModelLimits {
  // Triangles drawn, counting every node that instances a mesh (a wheel
  // mesh used by eight nodes counts eight times). An entity above this is
  // refused, not decimated: the model table should point at a coarser LOD.
  std::uint64_t max_triangles = 1'000'000;
  // Vertices in any one accessor (before triangles are assembled).
  std::uint64_t max_vertices = 4'000'000;
  // Bytes of the .gltf / .glb file and of each external buffer or image file.
  std::uint64_t max_file_bytes = 256ull << 20;
  // Texture pixels, all images of the model together (decoded to RGBA8:
  // 4 bytes each). Images beyond it are dropped with a warning.
  std::uint64_t max_texture_pixels = 32ull << 20;
  // Array and object nesting of the JSON: glTF needs about 8; far deeper
  // nesting can only be an attack on the parsers' recursion.
  int max_json_depth = 64;
};

}  // namespace ig::models
