#pragma once
// A model's bounds from its meshes and node transforms (models/model.h).

#include <optional>

#include "models/model.h"

namespace ig::models {

// The box and sphere holding every vertex of every node's mesh, each
// transformed to model space; nullopt when no node draws a vertex, or a
// transformed vertex is not finite (absurd scales).
std::optional<Bounds> compute_bounds(const Model& model);

}  // namespace ig::models
