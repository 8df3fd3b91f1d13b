#pragma once
// Reading a .gltf or .glb into TinyGLTF's model, with the checks TinyGLTF
// does not make first. Internal to the loader (models/model_loader.h).
//
// Before TinyGLTF: the file's size against the cap, the GLB container
// (models/glb_container.h), the JSON's nesting depth (TinyGLTF turns
// "extras" into its own values recursively: a deeply nested file would
// exhaust the stack), the asset version and the extensions the file
// requires. During: TinyGLTF reads external buffers and images through our
// file callbacks (the size cap; only the model's own folder, never the
// working directory TinyGLTF also searches) and decodes images through our
// callback, which checks an image's size from its header before decoding it
// and turns a bad or missing image into a warning instead of a failed model.

#include <map>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "models/model_limits.h"

namespace ig::models {

struct GltfDocument {
  tinygltf::Model gltf;
  // Why an image is not decoded, by image index: its header, its size, the
  // decoder. (An external image that was not found has no entry: TinyGLTF
  // leaves its pixels empty and its uri set.)
  std::map<int, std::string> image_failures;
};

// The extensions a file may list in extensionsRequired.
const std::vector<std::string>& supported_required_extensions();

// Throws ModelError with the reason (not the path); notes go to `warnings`.
GltfDocument read_gltf(const std::string& path, const ModelLimits& limits, std::vector<std::string>& warnings);

}  // namespace ig::models
