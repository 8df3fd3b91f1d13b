#pragma once
// glTF materials and their base colour images as models::Material and
// models::Image. Internal to the loader.

#include <map>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "models/model_image.h"
#include "models/model_material.h"

namespace ig::models {

struct ConvertedMaterials {
  std::vector<Material> materials;  // one per glTF material, same order
  std::vector<Image> images;        // only the decoded base colour images in use
  // Per material, the TEXCOORD_n set its base colour texture reads; -1
  // when it has no (usable) texture.
  std::vector<int> texcoord_set;
};

// `image_failures`: why images were not decoded (models/gltf_reader.h).
// Never throws for bad values: each is replaced by glTF's default with a
// warning, and a texture that cannot be used leaves the material untextured
// with a warning naming the image.
ConvertedMaterials convert_materials(const tinygltf::Model& gltf, const std::map<int, std::string>& image_failures,
                                     std::vector<std::string>& warnings);

}  // namespace ig::models
