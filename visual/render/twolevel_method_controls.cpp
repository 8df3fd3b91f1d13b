// TwoLevelMethod's side of TerrainMethod's generic controls: what Modbus
// and "as drawn" host answers reach through the interface.
#include "render/twolevel_method.h"

namespace ig::render {

void TwoLevelMethod::tune(const MethodTuning& tuning) {
  if (tuning.level1_thresholds) set_thresholds(tuning.level1_thresholds->first, tuning.level1_thresholds->second);
}

std::optional<LevelStatus> TwoLevelMethod::level_status() const {
  return LevelStatus{level1_size(), last_ratio()};
}

std::optional<double> TwoLevelMethod::coarse_height_at(double i, double j) const {
  // Level1 covers samples [origin, origin + size - 1] in both directions.
  const glm::ivec2 o = level1_origin();
  const int n = level1_size();
  if (i >= o.x && j >= o.y && i <= o.x + n - 1 && j <= o.y + n - 1) return std::nullopt;
  return level0_heights().height_at(i, j);
}

}  // namespace ig::render
