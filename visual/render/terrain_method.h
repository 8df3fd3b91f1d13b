#pragma once
// The interface every terrain LOD method implements (reference, two-level,
// and the baselines). A frame is: update() on the CPU (selection / LOD, no
// GL draw calls), then draw() issuing the passes into the bound target.
// Methods never read sockets or files; they see the camera and the scene.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "gl/render_target.h"
#include "render/camera.h"
#include "render/terrain_scene.h"

namespace ig::render {

struct MethodFrameStats {
  long long triangles = 0;  // triangles submitted this frame
  std::string passes;       // which passes ran, e.g. "terrain" or "level1+band+level0"
  // Method-specific per-frame columns, same names and order every frame.
  std::vector<std::pair<std::string, double>> columns;
};

class TerrainMethod {
 public:
  virtual ~TerrainMethod() = default;
  virtual std::string name() const = 0;
  // Names of the method-specific columns (fixed for the run).
  virtual std::vector<std::string> column_names() const = 0;
  // CPU-side LOD selection for this camera.
  virtual void update(const Camera& camera) = 0;
  // Draw into the target, which the caller has bound and cleared with
  // reversed-Z depth set up. A method with offscreen passes rebinds it after.
  virtual MethodFrameStats draw(const Camera& camera, const gl::RenderTarget& target) = 0;
};

struct TwoLevelOptions;  // render/twolevel_method.h

// Names accepted by make_method().
std::vector<std::string> method_names();
// Throws std::invalid_argument naming the method and the choices.
std::unique_ptr<TerrainMethod> make_method(const std::string& name, const TerrainScene& scene,
                                           const std::string& shader_dir, const TwoLevelOptions& twolevel);

}  // namespace ig::render
