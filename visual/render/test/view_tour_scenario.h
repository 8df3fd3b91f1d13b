#pragma once
// A scenario for GL tests: a rough 513^2 generated terrain (30 m spacing,
// 15.4 km square, 1400 m relief) and a path whose key k, at t = k, is view k
// exactly, so rendering frame k shows view k.
#include <string>
#include <vector>

#include "io/scenario.h"

namespace render_checks {

struct View {
  const char* name;
  double x, y, agl, heading, pitch;  // local metres, metres above ground, degrees
};

// A valley, a ridge seen from above and a skyline: the views of the checks
// that a pass leaves the picture as it was.
inline std::vector<View> valley_ridge_skyline() {
  return {{"valley", 4000, 3000, 120, 40, -4}, {"ridge", 7600, 7600, 400, 200, -12}, {"skyline", 2500, 9000, 60, 95, 2}};
}

inline ig::io::Scenario view_tour_scenario(const std::string& name, const std::vector<View>& views, int width,
                                           int height, double fov_y_deg) {
  ig::io::Scenario s;
  s.name = name;
  ig::options::SyntheticTerrainOptions g;
  g.size = 513;
  g.seed = 11;
  g.spacing_m = 30.0;
  g.relief_m = 1400.0;
  g.base_m = 200.0;
  s.terrain.generator = g;
  s.render.width = width;
  s.render.height = height;
  s.render.fov_y_deg = fov_y_deg;
  s.channels = {ig::io::ChannelSpec{}};
  s.path.frame = ig::io::PositionFrame::Local;
  s.path.altitude = ig::io::AltitudeMode::AboveGround;
  for (size_t k = 0; k < views.size(); ++k) {
    const View& v = views[k];
    s.path.keys.push_back(ig::io::PathKey{double(k), {v.x, v.y, v.agl}, v.heading, v.pitch, 0.0});
  }
  s.time_step_s = 1.0;
  s.duration_s = double(views.size() - 1);
  return s;
}

}  // namespace render_checks
