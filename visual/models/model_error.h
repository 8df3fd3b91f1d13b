#pragma once
// The loader's internal failure: thrown by the checking steps with the
// reason only, caught by load_model, which prefixes the file's path. Not
// part of the public interface (load_model never throws).

#include <cstddef>
#include <stdexcept>
#include <string>

namespace ig::models {

struct ModelError : std::runtime_error {
  explicit ModelError(const std::string& reason) : std::runtime_error(reason) {}
};

// "mesh 3 ('Wing')", "node 0": how messages name an element of the file.
inline std::string describe(const char* kind, std::size_t index, const std::string& name) {
  std::string s = std::string(kind) + " " + std::to_string(index);
  if (!name.empty()) s += " ('" + name + "')";
  return s;
}

}  // namespace ig::models
