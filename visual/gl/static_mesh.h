#pragma once
// A static mesh of int16 vertices (sample offsets, flags) with one or more
// index lists: built once, drawn many times per frame with the program and
// uniforms the caller set. The grid-based LOD methods draw through it, so
// they hold no GL names of their own.

#include <cstdint>
#include <vector>

#include "gl/gl_objects.h"

namespace ig::gl {

class StaticMesh {
 public:
  // One vertex attribute: `components` int16 values from `first` (in int16s
  // from the vertex's start), read as ivec by the vertex shader.
  struct Attribute {
    int components;
    int first;
  };

  StaticMesh() = default;
  // `stride` int16s per vertex; attribute k of `attributes` is shader location k.
  StaticMesh(const std::vector<std::int16_t>& vertices, int stride, const std::vector<Attribute>& attributes);

  // Adds an index list; returns its number for draw().
  int add_indices(const std::vector<std::uint32_t>& indices);
  int add_indices(const std::vector<std::uint16_t>& indices);
  int index_count(int list) const { return lists_[static_cast<std::size_t>(list)].count; }

  // Draws `count` indices of list `list` from index `first` as triangles.
  void draw(int list, int first, int count) const;
  void draw(int list) const { draw(list, 0, index_count(list)); }

 private:
  struct IndexList {
    Buffer buffer;
    int count = 0;
    bool wide = true;  // 32-bit indices, else 16-bit
  };
  VertexArray vao_;
  Buffer vbo_;
  std::vector<IndexList> lists_;
};

}  // namespace ig::gl
