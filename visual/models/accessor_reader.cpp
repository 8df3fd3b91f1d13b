#include "models/accessor_reader.h"

#include <algorithm>
#include <cstring>

#include "models/model_error.h"

namespace ig::models {

namespace {

int component_bytes(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;  // 5124 (int) and 5130 (double) are not glTF 2.0 accessor types
  }
}

int type_components(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

std::string n(std::uint64_t v) { return std::to_string(v); }

// One checked run of elements: `count` elements of `elem` bytes, `stride`
// apart, starting at `data` (all inside the buffer).
struct Span {
  const std::uint8_t* data = nullptr;
  std::uint64_t count = 0;
  std::uint64_t stride = 0;
};

// The bytes of `count` elements of `elem` bytes at `offset` in buffer view
// `view_index` (stride from the view, or packed), checked against the view
// and the view against its buffer.
Span checked_span(const tinygltf::Model& gltf, int view_index, std::uint64_t offset, std::uint64_t count,
                  std::uint64_t elem, bool allow_stride, const std::string& what) {
  if (view_index < 0 || std::size_t(view_index) >= gltf.bufferViews.size()) {
    throw ModelError(what + ": bufferView " + std::to_string(view_index) + " does not exist (" +
                     n(gltf.bufferViews.size()) + " bufferViews)");
  }
  const tinygltf::BufferView& view = gltf.bufferViews[std::size_t(view_index)];
  const std::string view_name = "bufferView " + std::to_string(view_index);
  if (view.buffer < 0 || std::size_t(view.buffer) >= gltf.buffers.size()) {
    throw ModelError(what + ": " + view_name + " refers to buffer " + std::to_string(view.buffer) +
                     ", which does not exist");
  }
  const std::uint64_t buffer_size = gltf.buffers[std::size_t(view.buffer)].data.size();
  // size_t from TinyGLTF; compared in 64 bits so no sum can wrap.
  const std::uint64_t view_offset = view.byteOffset, view_length = view.byteLength;
  if (view_offset > buffer_size || view_length > buffer_size - view_offset) {
    throw ModelError(what + ": " + view_name + " (bytes " + n(view_offset) + " + " + n(view_length) +
                     ") runs past the end of buffer " + std::to_string(view.buffer) + " (" + n(buffer_size) +
                     " bytes)");
  }
  std::uint64_t stride = elem;
  if (allow_stride && view.byteStride != 0) {
    stride = view.byteStride;
    if (stride < elem) {
      throw ModelError(what + ": " + view_name + "'s byteStride " + n(stride) + " is smaller than one element (" +
                       n(elem) + " bytes)");
    }
  }
  Span span;
  span.count = count;
  span.stride = stride;
  if (count == 0) return span;
  // Last byte read: offset + stride * (count - 1) + elem, which must not pass
  // view_length. offset <= view_length < 2^32 once checked, count <= 2^32
  // (callers cap it) and stride <= 252 (TinyGLTF checks), so nothing wraps.
  const std::uint64_t end = offset > view_length ? offset : offset + stride * (count - 1) + elem;
  if (end > view_length) {
    throw ModelError(what + ": " + n(count) + " elements from byte " + n(offset) + " need " + n(end) +
                     " bytes, past the end of " + view_name + " (" + n(view_length) + " bytes)");
  }
  span.data = gltf.buffers[std::size_t(view.buffer)].data.data() + view_offset + offset;
  return span;
}

// One component at `p` as a float (glTF 2.0 spec, "Animation" and
// "Meshes": the normalised conversions).
float component(const std::uint8_t* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      std::int8_t v;
      std::memcpy(&v, p, 1);
      return normalized ? std::max(float(v) / 127.0f, -1.0f) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? float(*p) / 255.0f : float(*p);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      std::int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? float(v) / 65535.0f : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return normalized ? float(double(v) / 4294967295.0) : float(v);
    }
    default: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

// One unsigned integer component (indices: byte, short or int).
std::uint32_t unsigned_component(const std::uint8_t* p, int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    default: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

const tinygltf::Accessor& checked_accessor(const tinygltf::Model& gltf, int index, const std::string& what) {
  if (index < 0 || std::size_t(index) >= gltf.accessors.size()) {
    throw ModelError(what + ": accessor " + std::to_string(index) + " does not exist (" + n(gltf.accessors.size()) +
                     " accessors)");
  }
  return gltf.accessors[std::size_t(index)];
}

// Reads accessor `index` component by component into `out` (count * comps
// values), sparse substitutions applied. `Convert` turns one component at a
// pointer into the output type.
template <typename T, typename Convert>
std::vector<T> read_accessor(const tinygltf::Model& gltf, int index, int comps, std::uint64_t max_count,
                             const std::string& what, Convert convert) {
  const tinygltf::Accessor& acc = checked_accessor(gltf, index, what);
  const std::string name = what + " (accessor " + std::to_string(index) + ")";
  const int cbytes = component_bytes(acc.componentType);
  if (cbytes == 0) throw ModelError(name + ": component type " + std::to_string(acc.componentType) + " is not valid");
  if (type_components(acc.type) != comps) {
    throw ModelError(name + ": has " + std::to_string(type_components(acc.type)) + " components per element, " +
                     std::to_string(comps) + " expected");
  }
  const std::uint64_t count = acc.count;
  if (count > max_count) {
    throw ModelError(name + ": " + n(count) + " elements, above the cap of " + n(max_count));
  }
  const std::uint64_t elem = std::uint64_t(cbytes) * std::uint64_t(comps);
  std::vector<T> out;
  if (acc.bufferView >= 0) {
    const Span span = checked_span(gltf, acc.bufferView, acc.byteOffset, count, elem, true, name);
    out.resize(std::size_t(count) * std::size_t(comps));
    for (std::uint64_t i = 0; i < count; ++i) {
      const std::uint8_t* e = span.data + i * span.stride;
      for (int c = 0; c < comps; ++c) out[std::size_t(i) * std::size_t(comps) + std::size_t(c)] = convert(e + c * cbytes, acc);
    }
  } else {
    out.assign(std::size_t(count) * std::size_t(comps), T{});  // no view: zeros, unless sparse
  }
  if (!acc.sparse.isSparse) return out;

  const auto& sp = acc.sparse;
  if (sp.count < 0 || std::uint64_t(sp.count) > count) {
    throw ModelError(name + ": sparse count " + std::to_string(sp.count) + " is not in 0.." + n(count));
  }
  const int icomp = sp.indices.componentType;
  if (icomp != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && icomp != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      icomp != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
    throw ModelError(name + ": sparse indices' component type " + std::to_string(icomp) + " is not unsigned");
  }
  if (sp.indices.byteOffset < 0 || sp.values.byteOffset < 0) throw ModelError(name + ": negative sparse byteOffset");
  const Span idx = checked_span(gltf, sp.indices.bufferView, std::uint64_t(sp.indices.byteOffset),
                                std::uint64_t(sp.count), std::uint64_t(component_bytes(icomp)), false,
                                name + " sparse indices");
  const Span val = checked_span(gltf, sp.values.bufferView, std::uint64_t(sp.values.byteOffset),
                                std::uint64_t(sp.count), elem, false, name + " sparse values");
  for (std::uint64_t k = 0; k < std::uint64_t(sp.count); ++k) {
    const std::uint64_t target = unsigned_component(idx.data + k * idx.stride, icomp);
    if (target >= count) {
      throw ModelError(name + ": sparse index " + n(target) + " is out of range (" + n(count) + " elements)");
    }
    const std::uint8_t* e = val.data + k * val.stride;
    for (int c = 0; c < comps; ++c) out[std::size_t(target) * std::size_t(comps) + std::size_t(c)] = convert(e + c * cbytes, acc);
  }
  return out;
}

}  // namespace

std::uint64_t accessor_count(const tinygltf::Model& gltf, int index, const std::string& what) {
  return checked_accessor(gltf, index, what).count;
}

std::vector<float> read_floats(const tinygltf::Model& gltf, int index, int components, std::uint64_t max_count,
                               const std::string& what) {
  // Counts are capped far below 2^32 so a stride (at most 255 bytes) times a
  // count stays well inside 64 bits.
  max_count = std::min<std::uint64_t>(max_count, 0xFFFFFFFFull);
  return read_accessor<float>(gltf, index, components, max_count, what,
                              [](const std::uint8_t* p, const tinygltf::Accessor& acc) {
                                return component(p, acc.componentType, acc.normalized);
                              });
}

std::vector<std::uint32_t> read_indices(const tinygltf::Model& gltf, int index, std::uint64_t max_count,
                                        const std::string& what) {
  const tinygltf::Accessor& acc = checked_accessor(gltf, index, what);
  const int t = acc.componentType;
  if (t != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && t != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      t != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
    throw ModelError(what + " (accessor " + std::to_string(index) + "): index component type " + std::to_string(t) +
                     " is not an unsigned integer type");
  }
  max_count = std::min<std::uint64_t>(max_count, 0xFFFFFFFFull);
  return read_accessor<std::uint32_t>(gltf, index, 1, max_count, what,
                                      [](const std::uint8_t* p, const tinygltf::Accessor& a) {
                                        return unsigned_component(p, a.componentType);
                                      });
}

}  // namespace ig::models
