#pragma once
// Loading an entity model from a glTF 2.0 file (.gltf with its buffers and
// images, or .glb), through TinyGLTF, with every value checked
// (docs/models.md).
//
// A model is either loaded whole or refused with one reason; nothing in a
// file can crash the loader, make it hang or put a NaN in the result.
// Refused: a missing, empty, truncated or garbled file; a missing external
// buffer; a NaN or infinite vertex position; an index past the vertices; an
// accessor or buffer view running past its data; a required extension the
// IG does not support; a node with two parents or a loop of nodes; more
// triangles than ModelLimits allows (counting instancing); nothing to draw.
// Loaded with a warning: a missing or undecodable texture (the model is
// drawn without it), points and lines (skipped), a missing default scene
// (scene 0, else every root node), unusable normals (computed).

#include <optional>
#include <string>
#include <vector>

#include "models/model.h"
#include "models/model_limits.h"

namespace ig::models {

struct ModelLoad {
  std::optional<Model> model;         // set when the file was loaded
  std::vector<std::string> warnings;  // each "<path>: <what was dropped or assumed>"
  std::string error;                  // "<path>: <reason>" when refused; empty when loaded

  bool ok() const { return model.has_value(); }
};

// Never throws.
ModelLoad load_model(const std::string& path, const ModelLimits& limits = {});

}  // namespace ig::models
