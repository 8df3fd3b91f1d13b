#include "session/drawn_surface.h"

#include "render/twolevel_method.h"
#include "session/scenario_runner.h"

namespace ig::session {

std::optional<double> DrawnSurface::level0_height_at(double x_m, double y_m) {
  const auto* method = dynamic_cast<const render::TwoLevelMethod*>(&runner_.method());
  if (!method) return std::nullopt;
  const terrain::Heightfield& hf = runner_.heightfield();
  const double i = x_m / hf.spacing_x_m, j = y_m / hf.spacing_y_m;
  // Level1 covers samples [origin, origin + size - 1] in both directions.
  const glm::ivec2 o = method->level1_origin();
  const int n = method->level1_size();
  if (i >= o.x && j >= o.y && i <= o.x + n - 1 && j <= o.y + n - 1) return std::nullopt;
  return method->level0_heights().height_at(i, j);
}

}  // namespace ig::session
