#pragma once
// From glTF's axes to the simulator's body axes.
//
// A glTF model is in metres, right-handed, +Y up and its front facing +Z
// (glTF 2.0 spec, "Coordinate System and Units"); so its right is -X.
// The simulator's body axes (docs/models.md) are x forward, y right, z down
// (right-handed too). The change is a pure rotation (determinant +1, no
// scale): body x = glTF z, body y = -glTF x, body z = -glTF y.
//
//   body_from_gltf() * glm::vec4(0, 0, 1, 0) == (1, 0, 0, 0)   nose: forward
//   body_from_gltf() * glm::vec4(-1, 0, 0, 0) == (0, 1, 0, 0)  right wing: right
//   body_from_gltf() * glm::vec4(0, 1, 0, 0) == (0, 0, -1, 0)  up: minus down

#include <glm/mat4x4.hpp>

namespace ig::models {

inline glm::mat4 body_from_gltf() {
  // glm is column-major: each column is where one glTF axis goes.
  return glm::mat4(glm::vec4(0.0f, -1.0f, 0.0f, 0.0f),   // glTF +X (left) -> body -y
                   glm::vec4(0.0f, 0.0f, -1.0f, 0.0f),   // glTF +Y (up)   -> body -z
                   glm::vec4(1.0f, 0.0f, 0.0f, 0.0f),    // glTF +Z (front)-> body +x
                   glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
}

}  // namespace ig::models
