#include "models/primitive_builder.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "models/accessor_reader.h"
#include "models/model_error.h"

namespace ig::models {

namespace {

const char* mode_name(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS: return "points";
    case TINYGLTF_MODE_LINE: return "lines";
    case TINYGLTF_MODE_LINE_LOOP: return "a line loop";
    case TINYGLTF_MODE_LINE_STRIP: return "a line strip";
    case TINYGLTF_MODE_TRIANGLES: return "triangles";
    case TINYGLTF_MODE_TRIANGLE_STRIP: return "a triangle strip";
    case TINYGLTF_MODE_TRIANGLE_FAN: return "a triangle fan";
    default: return "an unknown mode";
  }
}

int effective_mode(const tinygltf::Primitive& prim) { return prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode; }

bool is_triangles(int mode) {
  return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

int attribute(const tinygltf::Primitive& prim, const std::string& name) {
  const auto it = prim.attributes.find(name);
  return it == prim.attributes.end() ? -1 : it->second;
}

// The triangle list of `idx` drawn in `mode`. Strips and fans follow the
// glTF spec's vertex order (a strip's odd triangles swap two vertices so all
// keep the same winding); their degenerate triangles (a repeated vertex,
// which stitch strips together) are dropped.
std::vector<std::uint32_t> assemble(const std::vector<std::uint32_t>& idx, int mode, const std::string& what,
                                    std::vector<std::string>& warnings) {
  std::vector<std::uint32_t> tri;
  const std::size_t n = idx.size();
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    if (n % 3 != 0) {
      warnings.push_back(what + ": " + std::to_string(n) + " indices, not a multiple of 3: the last " +
                         std::to_string(n % 3) + " ignored");
    }
    tri.assign(idx.begin(), idx.begin() + std::ptrdiff_t(n - n % 3));
    return tri;
  }
  if (n < 3) return tri;
  tri.reserve((n - 2) * 3);
  for (std::size_t i = 0; i + 2 < n; ++i) {
    std::uint32_t a, b, c;
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      a = idx[i];
      b = idx[i + 1 + i % 2];
      c = idx[i + 2 - i % 2];
    } else {  // fan: about the first vertex
      a = idx[i + 1];
      b = idx[i + 2];
      c = idx[0];
    }
    if (a == b || b == c || a == c) continue;
    tri.insert(tri.end(), {a, b, c});
  }
  return tri;
}

glm::vec3 unit_or(glm::dvec3 v, glm::vec3 fallback) {
  const double len = glm::length(v);
  if (!(len > 1e-30) || !std::isfinite(len)) return fallback;
  return glm::vec3(v / len);
}

// A triangle's normal by the right-hand rule (counter-clockwise is the
// front in glTF); +Y for a degenerate triangle, which shows no surface.
glm::vec3 face_normal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::dvec3 e1 = glm::dvec3(b) - glm::dvec3(a), e2 = glm::dvec3(c) - glm::dvec3(a);
  return unit_or(glm::cross(e1, e2), glm::vec3(0.0f, 1.0f, 0.0f));
}

// The file's normals, unit length; empty (with a warning) when they cannot
// be used, so the caller computes them.
std::vector<glm::vec3> file_normals(const tinygltf::Model& gltf, int accessor, std::size_t nv,
                                    const ModelLimits& limits, const std::string& what,
                                    std::vector<std::string>& warnings) {
  const std::vector<float> raw = read_floats(gltf, accessor, 3, limits.max_vertices, what + " NORMAL");
  if (raw.size() / 3 != nv) {
    warnings.push_back(what + ": NORMAL has " + std::to_string(raw.size() / 3) + " elements, POSITION " +
                       std::to_string(nv) + ": normals computed instead");
    return {};
  }
  std::vector<glm::vec3> normals(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    const glm::dvec3 v(raw[3 * i], raw[3 * i + 1], raw[3 * i + 2]);
    const double len = glm::length(v);
    if (!std::isfinite(len) || !(len > 1e-12)) {
      warnings.push_back(what + ": NORMAL " + std::to_string(i) + " is zero, NaN or infinite: normals computed instead");
      return {};
    }
    normals[i] = glm::vec3(v / len);
  }
  return normals;
}

std::vector<glm::vec2> file_texcoords(const tinygltf::Model& gltf, const tinygltf::Primitive& prim, int set,
                                      std::size_t nv, const ModelLimits& limits, const std::string& what,
                                      std::vector<std::string>& warnings) {
  const std::string name = "TEXCOORD_" + std::to_string(set);
  const int accessor = attribute(prim, name);
  if (accessor < 0) {
    warnings.push_back(what + ": its material's texture uses " + name + ", which the primitive lacks: drawn untextured");
    return {};
  }
  const std::vector<float> raw = read_floats(gltf, accessor, 2, limits.max_vertices, what + " " + name);
  if (raw.size() / 2 != nv) {
    warnings.push_back(what + ": " + name + " has " + std::to_string(raw.size() / 2) + " elements, POSITION " +
                       std::to_string(nv) + ": drawn untextured");
    return {};
  }
  std::vector<glm::vec2> uv(nv);
  std::size_t bad = 0;
  for (std::size_t i = 0; i < nv; ++i) {
    uv[i] = glm::vec2(raw[2 * i], raw[2 * i + 1]);
    if (!std::isfinite(uv[i].x) || !std::isfinite(uv[i].y)) {
      uv[i] = glm::vec2(0.0f);
      ++bad;
    }
  }
  if (bad > 0) warnings.push_back(what + ": " + std::to_string(bad) + " NaN or infinite " + name + " set to (0, 0)");
  return uv;
}

}  // namespace

std::uint64_t primitive_triangle_bound(const tinygltf::Model& gltf, const tinygltf::Primitive& prim,
                                       const std::string& what) {
  const int mode = effective_mode(prim);
  const int position = attribute(prim, "POSITION");
  if (!is_triangles(mode) || position < 0) return 0;
  const std::uint64_t n =
      prim.indices >= 0 ? accessor_count(gltf, prim.indices, what + " indices") : accessor_count(gltf, position, what + " POSITION");
  if (mode == TINYGLTF_MODE_TRIANGLES) return n / 3;
  return n >= 3 ? n - 2 : 0;
}

std::optional<Primitive> build_primitive(const tinygltf::Model& gltf, const tinygltf::Primitive& prim,
                                         const std::string& what, int texcoord_set, const ModelLimits& limits,
                                         std::vector<std::string>& warnings) {
  const int mode = effective_mode(prim);
  if (!is_triangles(mode)) {
    warnings.push_back(what + ": " + mode_name(mode) + " (mode " + std::to_string(mode) +
                       ") skipped: only triangles are drawn");
    return std::nullopt;
  }
  const int position = attribute(prim, "POSITION");
  if (position < 0) {
    warnings.push_back(what + ": no POSITION attribute: skipped");
    return std::nullopt;
  }

  const std::vector<float> raw = read_floats(gltf, position, 3, limits.max_vertices, what + " POSITION");
  const std::size_t nv = raw.size() / 3;
  std::vector<glm::vec3> pos(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    pos[i] = glm::vec3(raw[3 * i], raw[3 * i + 1], raw[3 * i + 2]);
    if (!std::isfinite(pos[i].x) || !std::isfinite(pos[i].y) || !std::isfinite(pos[i].z)) {
      throw ModelError(what + ": vertex " + std::to_string(i) + "'s POSITION is NaN or infinite");
    }
  }

  std::vector<std::uint32_t> idx;
  if (prim.indices >= 0) {
    idx = read_indices(gltf, prim.indices, 3 * limits.max_triangles + 2, what + " indices");
    for (std::size_t k = 0; k < idx.size(); ++k) {
      if (idx[k] >= nv) {
        throw ModelError(what + ": index " + std::to_string(idx[k]) + " (index number " + std::to_string(k) +
                         ") is out of range (" + std::to_string(nv) + " vertices)");
      }
    }
  } else {
    idx.resize(nv);
    for (std::size_t i = 0; i < nv; ++i) idx[i] = std::uint32_t(i);
  }
  const std::vector<std::uint32_t> tri = assemble(idx, mode, what, warnings);
  if (tri.empty()) {
    warnings.push_back(what + ": no triangles: skipped");
    return std::nullopt;
  }

  const int normal = attribute(prim, "NORMAL");
  std::vector<glm::vec3> nrm;
  if (normal >= 0) nrm = file_normals(gltf, normal, nv, limits, what, warnings);
  std::vector<glm::vec2> uv;
  if (texcoord_set >= 0) uv = file_texcoords(gltf, prim, texcoord_set, nv, limits, what, warnings);

  Primitive out;
  out.material = prim.material;
  if (nrm.empty()) {
    // Flat normals (glTF: "When normals are not specified, client
    // implementations MUST calculate flat normals"): each triangle its own
    // three vertices.
    out.positions.reserve(tri.size());
    out.normals.reserve(tri.size());
    for (std::size_t t = 0; t < tri.size(); t += 3) {
      const glm::vec3 n = face_normal(pos[tri[t]], pos[tri[t + 1]], pos[tri[t + 2]]);
      for (int k = 0; k < 3; ++k) {
        out.indices.push_back(std::uint32_t(out.positions.size()));
        out.positions.push_back(pos[tri[t + std::size_t(k)]]);
        out.normals.push_back(n);
        if (!uv.empty()) out.texcoords.push_back(uv[tri[t + std::size_t(k)]]);
      }
    }
    return out;
  }
  // Shared vertices: keep the ones the triangles use, in first-use order.
  std::vector<std::uint32_t> remap(nv, UINT32_MAX);
  out.indices.reserve(tri.size());
  for (std::uint32_t v : tri) {
    if (remap[v] == UINT32_MAX) {
      remap[v] = std::uint32_t(out.positions.size());
      out.positions.push_back(pos[v]);
      out.normals.push_back(nrm[v]);
      if (!uv.empty()) out.texcoords.push_back(uv[v]);
    }
    out.indices.push_back(remap[v]);
  }
  return out;
}

}  // namespace ig::models
