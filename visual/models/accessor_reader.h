#pragma once
// Reading glTF accessors without trusting them. Internal to the loader.
//
// TinyGLTF parses accessors and buffer views but never checks that an
// accessor's elements lie inside its buffer view, or the view inside its
// buffer; reading as the file says could run past the end of the data.
// Here every range is checked in 64-bit arithmetic before a byte is read,
// counts are capped before anything is allocated, and sparse accessors are
// applied (TinyGLTF only parses them). Each failure is a ModelError naming
// the accessor and what is wrong with it.

#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace ig::models {

// The element count of accessor `index`, after checking the index exists.
// `what` names the user in messages ("mesh 0 ('hull') primitive 1 POSITION").
std::uint64_t accessor_count(const tinygltf::Model& gltf, int index, const std::string& what);

// Accessor `index` as `components` floats per element (its type must have
// exactly that many components), converted from any component type, with
// glTF's normalisation when the accessor is `normalized`. Values are as
// stored: the caller checks they are finite. At most max_count elements.
std::vector<float> read_floats(const tinygltf::Model& gltf, int index, int components, std::uint64_t max_count,
                               const std::string& what);

// Accessor `index` as unsigned indices (SCALAR, unsigned byte, short or int).
std::vector<std::uint32_t> read_indices(const tinygltf::Model& gltf, int index, std::uint64_t max_count,
                                        const std::string& what);

}  // namespace ig::models
