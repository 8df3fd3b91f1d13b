#include "session/drawn_surface.h"

#include "session/scenario_runner.h"

namespace ig::session {

std::optional<double> DrawnSurface::level0_height_at(double x_m, double y_m) {
  const terrain::Heightfield& hf = runner_.heightfield();
  return runner_.method().coarse_height_at(x_m / hf.spacing_x_m, y_m / hf.spacing_y_m);
}

}  // namespace ig::session
