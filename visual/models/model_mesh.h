#pragma once
// A model's geometry as a renderer uploads it: triangle lists with one
// normal per vertex and, where the material has a texture, one texture
// coordinate per vertex. No GL.
//
// Whatever the file held (strips, fans, 8- or 16-bit indices, quantized
// attributes, sparse accessors, interleaved views), the loader turns it into
// this one shape, so the renderer has a single vertex layout and a single
// draw mode. Every value is finite; every index is below positions.size().

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ig::models {

struct Primitive {
  std::vector<glm::vec3> positions;     // metres, in the owning node's frame (glTF axes)
  std::vector<glm::vec3> normals;       // unit length, one per position
  // The base colour texture's coordinates (its TEXCOORD_n set), one per
  // position; (0, 0) is the image's first pixel row, as glTF defines it.
  // Empty when the material has no usable texture or the primitive lacks
  // the set: then the primitive is drawn untextured, in the base colour.
  std::vector<glm::vec2> texcoords;
  std::vector<std::uint32_t> indices;   // triangle list: 3 per triangle
  int material = -1;                    // index into Model::materials; -1: the default material

  std::size_t triangle_count() const { return indices.size() / 3; }
};

struct Mesh {
  std::string name;  // may be empty
  std::vector<Primitive> primitives;

  std::size_t triangle_count() const {
    std::size_t n = 0;
    for (const Primitive& p : primitives) n += p.triangle_count();
    return n;
  }
};

}  // namespace ig::models
