#pragma once
// The terrain height as the last frame drew it, for "as drawn" HOT answers
// (ig serve --host-surface drawn, docs/host-services.md): the
// full-resolution surface inside the two-level method's Level1 square, its
// Level0 mesh outside it. Other methods: nullopt (answers stay full
// resolution). Read on the frame loop's thread, after a frame was rendered.

#include <optional>

namespace ig::session {

class ScenarioRunner;

class DrawnSurface {
 public:
  explicit DrawnSurface(ScenarioRunner& runner) : runner_(runner) {}
  // Height drawn at terrain-local (x, y) where Level0 is drawn; nullopt
  // inside Level1 (the full-resolution surface) or without a two-level method.
  // Reads the method's own Level0 height query, so a rebuilt method is followed.
  std::optional<double> level0_height_at(double x_m, double y_m);

 private:
  ScenarioRunner& runner_;
};

}  // namespace ig::session
