// The one place that maps method names to implementations.
#include <cmath>
#include <stdexcept>

#include "render/reference_method.h"
#include "render/terrain_method.h"
#include "render/twolevel_method.h"

namespace ig::render {

double pixels_per_radian(const Camera& camera, int viewport_height_px) {
  return 0.5 * viewport_height_px / std::tan(0.5 * camera.fov_y_deg * M_PI / 180.0);
}

std::vector<std::string> method_names() { return {"twolevel", "reference"}; }

std::unique_ptr<TerrainMethod> make_method(const std::string& name, const TerrainScene& scene,
                                           const std::string& shader_dir, const TwoLevelOptions& twolevel,
                                           std::optional<double> knob) {
  if (name == "reference") return std::make_unique<ReferenceMethod>(scene, shader_dir);
  if (name == "twolevel") {
    TwoLevelOptions o = twolevel;
    if (knob) o.level0_budget = int(*knob);
    return std::make_unique<TwoLevelMethod>(scene, shader_dir, o);
  }
  std::string choices;
  for (const auto& n : method_names()) choices += (choices.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown method '" + name + "' (available: " + choices + ")");
}

std::vector<double> knob_sweep(const std::string& name) {
  if (name == "twolevel") return {512, 1024, 2048, 4096, 8192};
  return {};
}

}  // namespace ig::render
