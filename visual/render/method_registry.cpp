// The one place that maps method names to implementations.
#include <stdexcept>

#include "render/reference_method.h"
#include "render/terrain_method.h"
#include "render/twolevel_method.h"

namespace ig::render {

std::vector<std::string> method_names() { return {"twolevel", "reference"}; }

std::unique_ptr<TerrainMethod> make_method(const std::string& name, const TerrainScene& scene,
                                           const std::string& shader_dir, const TwoLevelOptions& twolevel) {
  if (name == "reference") return std::make_unique<ReferenceMethod>(scene, shader_dir);
  if (name == "twolevel") return std::make_unique<TwoLevelMethod>(scene, shader_dir, twolevel);
  std::string choices;
  for (const auto& n : method_names()) choices += (choices.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown method '" + name + "' (available: " + choices + ")");
}

}  // namespace ig::render
