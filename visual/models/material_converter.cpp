#include "models/material_converter.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "models/model_error.h"

namespace ig::models {

namespace {

TextureWrap wrap_mode(int gl_wrap) {
  switch (gl_wrap) {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::ClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::MirroredRepeat;
    default: return TextureWrap::Repeat;
  }
}

// The name messages use for image `i`: its name, else its file, else its index.
std::string image_label(const tinygltf::Image& image, int i) {
  std::string label = "image " + std::to_string(i);
  if (!image.name.empty()) return label + " ('" + image.name + "')";
  if (!image.uri.empty() && image.uri.rfind("data:", 0) != 0) return label + " ('" + image.uri + "')";
  return label;
}

// TinyGLTF's decoded pixels as RGBA8; false when they are not what the
// header says (then the texture is dropped).
bool to_rgba8(const tinygltf::Image& in, Image& out) {
  const int c = in.component;
  const int bytes = in.bits == 16 ? 2 : in.bits == 8 ? 1 : 0;
  if (in.width <= 0 || in.height <= 0 || c < 1 || c > 4 || bytes == 0) return false;
  const std::size_t pixels = std::size_t(in.width) * std::size_t(in.height);
  if (in.image.size() != pixels * std::size_t(c) * std::size_t(bytes)) return false;
  out.width = in.width;
  out.height = in.height;
  out.rgba.resize(pixels * 4);
  auto sample = [&](std::size_t p, int ch) -> std::uint8_t {
    const std::size_t at = (p * std::size_t(c) + std::size_t(ch)) * std::size_t(bytes);
    // 16-bit samples are native-endian uint16 from stb: keep the high byte.
    if (bytes == 2) {
      std::uint16_t v;
      std::memcpy(&v, &in.image[at], 2);
      return std::uint8_t(v >> 8);
    }
    return in.image[at];
  };
  for (std::size_t p = 0; p < pixels; ++p) {
    std::uint8_t* o = &out.rgba[p * 4];
    if (c <= 2) {  // grey (+ alpha)
      o[0] = o[1] = o[2] = sample(p, 0);
      o[3] = c == 2 ? sample(p, 1) : 255;
    } else {
      o[0] = sample(p, 0);
      o[1] = sample(p, 1);
      o[2] = sample(p, 2);
      o[3] = c == 4 ? sample(p, 3) : 255;
    }
  }
  return true;
}

}  // namespace

ConvertedMaterials convert_materials(const tinygltf::Model& gltf, const std::map<int, std::string>& image_failures,
                                     std::vector<std::string>& warnings) {
  ConvertedMaterials out;
  std::map<int, int> image_slot;  // glTF image -> index in out.images, -1 when it cannot be used
  for (std::size_t m = 0; m < gltf.materials.size(); ++m) {
    const tinygltf::Material& gm = gltf.materials[m];
    const std::string what = describe("material", m, gm.name);
    Material mat;
    mat.name = gm.name;

    const std::vector<double>& f = gm.pbrMetallicRoughness.baseColorFactor;
    if (f.size() == 4 && std::all_of(f.begin(), f.end(), [](double v) { return std::isfinite(v); })) {
      for (int k = 0; k < 4; ++k) mat.base_color[k] = float(std::clamp(f[std::size_t(k)], 0.0, 1.0));
    } else {
      warnings.push_back(what + ": baseColorFactor is not 4 finite numbers: white used");
    }

    if (gm.alphaMode == "MASK") {
      mat.alpha_mode = AlphaMode::Mask;
    } else if (gm.alphaMode == "BLEND") {
      mat.alpha_mode = AlphaMode::Blend;
    } else if (!gm.alphaMode.empty() && gm.alphaMode != "OPAQUE") {
      warnings.push_back(what + ": alphaMode \"" + gm.alphaMode + "\" is not OPAQUE, MASK or BLEND: opaque used");
    }
    mat.alpha_cutoff = std::isfinite(gm.alphaCutoff) ? float(std::clamp(gm.alphaCutoff, 0.0, 1.0)) : 0.5f;
    mat.double_sided = gm.doubleSided;
    mat.unlit = gm.extensions.count("KHR_materials_unlit") > 0;

    int texcoord = -1;
    const tinygltf::TextureInfo& info = gm.pbrMetallicRoughness.baseColorTexture;
    if (info.index >= 0) {
      const std::string tex_what = what + ": base colour texture " + std::to_string(info.index);
      if (std::size_t(info.index) >= gltf.textures.size()) {
        warnings.push_back(tex_what + " does not exist: drawn untextured");
      } else if (const tinygltf::Texture& tex = gltf.textures[std::size_t(info.index)];
                 tex.source < 0 || std::size_t(tex.source) >= gltf.images.size()) {
        warnings.push_back(tex_what + " has no image the IG can read (source " + std::to_string(tex.source) +
                           "): drawn untextured");
      } else if (info.texCoord < 0 || info.texCoord > 7) {
        warnings.push_back(tex_what + ": texCoord " + std::to_string(info.texCoord) + " is not valid: drawn untextured");
      } else {
        const int src = tex.source;
        auto slot = image_slot.find(src);
        if (slot == image_slot.end()) {
          const tinygltf::Image& gi = gltf.images[std::size_t(src)];
          Image img;
          img.name = !gi.name.empty() ? gi.name : (gi.uri.rfind("data:", 0) == 0 ? std::string() : gi.uri);
          int index = -1;
          const auto failure = image_failures.find(src);
          if (failure != image_failures.end()) {
            warnings.push_back(image_label(gi, src) + " not loaded (" + failure->second +
                               "): its materials are drawn untextured");
          } else if (gi.image.empty()) {
            warnings.push_back(image_label(gi, src) +
                               " not loaded (file missing, empty or unreadable): its materials are drawn untextured");
          } else if (!to_rgba8(gi, img)) {
            warnings.push_back(image_label(gi, src) + " not loaded (decoded pixels do not match its size)" +
                               ": its materials are drawn untextured");
          } else {
            index = int(out.images.size());
            out.images.push_back(std::move(img));
          }
          slot = image_slot.emplace(src, index).first;
        }
        if (slot->second >= 0) {
          mat.base_color_image = slot->second;
          texcoord = info.texCoord;
          if (tex.sampler >= 0 && std::size_t(tex.sampler) < gltf.samplers.size()) {
            mat.wrap_s = wrap_mode(gltf.samplers[std::size_t(tex.sampler)].wrapS);
            mat.wrap_t = wrap_mode(gltf.samplers[std::size_t(tex.sampler)].wrapT);
          }
        }
      }
    }
    out.materials.push_back(std::move(mat));
    out.texcoord_set.push_back(texcoord);
  }
  return out;
}

}  // namespace ig::models
