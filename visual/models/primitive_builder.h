#pragma once
// One glTF mesh primitive turned into a checked triangle list
// (models/model_mesh.h). Internal to the loader.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "models/model_limits.h"
#include "models/model_mesh.h"

namespace ig::models {

// Triangles the primitive will have at most, from its accessors' counts,
// before reading any data (0 for points, lines and unknown modes). The
// triangle cap is checked with this before memory is spent.
std::uint64_t primitive_triangle_bound(const tinygltf::Model& gltf, const tinygltf::Primitive& prim,
                                       const std::string& what);

// The primitive as a triangle list; nullopt (with a warning) when it has
// nothing to draw: points or lines, no POSITION. `texcoord_set`: the
// TEXCOORD_n the material's base colour texture uses, -1 for none.
// Strips and fans become lists; missing normals are computed flat, as the
// glTF spec requires; vertices no triangle uses are dropped. Throws
// ModelError for a NaN or infinite position, an index out of range or an
// accessor that does not fit its data.
std::optional<Primitive> build_primitive(const tinygltf::Model& gltf, const tinygltf::Primitive& prim,
                                         const std::string& what, int texcoord_set, const ModelLimits& limits,
                                         std::vector<std::string>& warnings);

}  // namespace ig::models
