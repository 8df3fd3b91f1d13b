#include "terrain/back_faces_hidden.h"

#include <algorithm>
#include <cmath>

namespace ig::terrain {

bool back_faces_hidden(const Heightfield& hf, const glm::dvec3& local_eye) {
  if (!std::isfinite(local_eye.x) || !std::isfinite(local_eye.y) || !std::isfinite(local_eye.z)) return false;
  const double gx = local_eye.x / hf.spacing_x_m, gy = local_eye.y / hf.spacing_y_m;
  if (gx < 0.0 || gy < 0.0 || gx > hf.width - 1 || gy > hf.height - 1) return local_eye.z > hf.max_m;
  const int i = std::min(int(gx), hf.width - 2), j = std::min(int(gy), hf.height - 2);
  const float top = std::max({hf.at(i, j), hf.at(i + 1, j), hf.at(i, j + 1), hf.at(i + 1, j + 1)});
  return local_eye.z > top;
}

}  // namespace ig::terrain
